namespace GMac.Benchmarks.Kernels.Values;

/// <summary>A rotation by an angle about the line through a point along an axis (of any length), and the point it moves.</summary>
public struct AxisRotationInput
{
    public Vec3 Axis;
    public Vec3 Origin;
    public double Angle;
    public Vec3 Point;
}
