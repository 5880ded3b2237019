namespace Twister.Tests.Tessellation.Shapes;

/// <summary>A height field z = f(x, y) over the unit square, with x = u and y = v.</summary>
internal sealed class HeightSheet(Func<double, double, double> height, Func<double, double, double> dx, Func<double, double, double> dy) : IParametricSurface
{
    /// <summary>Gentle waves: curvature spread evenly over the square.</summary>
    public static HeightSheet Wavy() => new(
        (x, y) => 0.1 * Math.Sin(2 * Math.PI * x) * Math.Sin(2 * Math.PI * y),
        (x, y) => 0.2 * Math.PI * Math.Cos(2 * Math.PI * x) * Math.Sin(2 * Math.PI * y),
        (x, y) => 0.2 * Math.PI * Math.Sin(2 * Math.PI * x) * Math.Cos(2 * Math.PI * y));

    /// <summary>A flat sheet with one narrow bump: all the curvature in a small part of the square.</summary>
    public static HeightSheet Bump()
    {
        const double h = 0.3, w2 = 0.01, cx = 0.3, cy = 0.6;
        double F(double x, double y) => h * Math.Exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / w2);
        return new(F, (x, y) => -2 * (x - cx) / w2 * F(x, y), (x, y) => -2 * (y - cy) / w2 * F(x, y));
    }

    public TwistablePoint PointAt(double u, double v) => new(u, v, height(u, v));

    /// <summary>(1, 0, f_x) × (0, 1, f_y) = (−f_x, −f_y, 1).</summary>
    public TwistableVector NormalAt(double u, double v) => new(-dx(u, v), -dy(u, v), 1);
}
