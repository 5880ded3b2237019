namespace Twister.Tests.Tessellation.Shapes;

/// <summary>Sphere about the origin: u around the z axis, v from the south pole (v = 0) to the north pole.</summary>
internal sealed class SphereSurface(double radius) : IParametricSurface
{
    public double Radius => radius;

    public TwistablePoint PointAt(double u, double v)
    {
        var d = Direction(u, v);
        return new(radius * d.x, radius * d.y, radius * d.z);
    }

    /// <summary>∂S/∂u × ∂S/∂v = 2π² r² sin(πv) times the outward unit normal: zero at the poles.</summary>
    public TwistableVector NormalAt(double u, double v)
    {
        var d = Direction(u, v);
        var k = 2 * Math.PI * Math.PI * radius * radius * Math.Sin(Math.PI * v);
        return new(k * d.x, k * d.y, k * d.z);
    }

    public static TwistableVector Direction(double u, double v)
    {
        double theta = 2 * Math.PI * u, phi = Math.PI * v;
        return new(Math.Sin(phi) * Math.Cos(theta), Math.Sin(phi) * Math.Sin(theta), -Math.Cos(phi));
    }
}
