namespace Twister.Tests.Tessellation.Shapes;

/// <summary>Torus about the z axis: u around the axis, v around the tube.</summary>
internal sealed class TorusSurface(double major, double minor) : IParametricSurface
{
    public double Major => major;

    public double Minor => minor;

    public TwistablePoint PointAt(double u, double v)
    {
        double a = 2 * Math.PI * u, b = 2 * Math.PI * v, ring = major + minor * Math.Cos(b);
        return new(ring * Math.Cos(a), ring * Math.Sin(a), minor * Math.Sin(b));
    }

    /// <summary>∂S/∂u × ∂S/∂v = 4π² r (R + r cos 2πv) times the outward unit normal.</summary>
    public TwistableVector NormalAt(double u, double v)
    {
        var n = OutwardNormal(u, v);
        var k = 4 * Math.PI * Math.PI * minor * (major + minor * Math.Cos(2 * Math.PI * v));
        return new(k * n.x, k * n.y, k * n.z);
    }

    public static TwistableVector OutwardNormal(double u, double v)
    {
        double a = 2 * Math.PI * u, b = 2 * Math.PI * v;
        return new(Math.Cos(b) * Math.Cos(a), Math.Cos(b) * Math.Sin(a), Math.Sin(b));
    }
}
