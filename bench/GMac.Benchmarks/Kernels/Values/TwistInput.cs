namespace GMac.Benchmarks.Kernels.Values;

/// <summary>The arguments of the Figure 6-6 twist: a rotation about an axis through a point, a slide along the axis, and the moved point.</summary>
public struct TwistInput
{
    public Vec3 Axis;
    public Vec3 Origin;
    public double Angle;
    public double Slide;
    public Vec3 Point;
}
