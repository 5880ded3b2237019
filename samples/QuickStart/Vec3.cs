namespace QuickStart;

/// <summary>A 3D point or vector with the lower-case fields the GMacDSL class bindings (Vector3D, ConformalPoint3D) read.</summary>
public struct Vec3(double x, double y, double z)
{
    public double x = x;
    public double y = y;
    public double z = z;

    public static Vec3 operator -(Vec3 a, Vec3 b) => new(a.x - b.x, a.y - b.y, a.z - b.z);
    public static Vec3 operator +(Vec3 a, Vec3 b) => new(a.x + b.x, a.y + b.y, a.z + b.z);
    public static Vec3 operator *(double s, Vec3 a) => new(s * a.x, s * a.y, s * a.z);

    public readonly double Dot(Vec3 b) => x * b.x + y * b.y + z * b.z;

    public readonly Vec3 Cross(Vec3 b) => new(y * b.z - z * b.y, z * b.x - x * b.z, x * b.y - y * b.x);

    public override readonly string ToString() => FormattableString.Invariant($"({x:0.000000}, {y:0.000000}, {z:0.000000})");
}
