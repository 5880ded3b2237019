namespace GMac.Benchmarks.Kernels.Values;

/// <summary>A 3D vector with the members x, y, z that the DSL class bindings Vector3D and Point3D read.</summary>
public struct Vec3
{
    public double x;
    public double y;
    public double z;

    public Vec3(double x, double y, double z) => (this.x, this.y, this.z) = (x, y, z);
}
