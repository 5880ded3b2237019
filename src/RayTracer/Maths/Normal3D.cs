using System.Runtime.CompilerServices;

namespace RayTracer.Maths;

/// <summary>
/// A surface normal. Kept distinct from <see cref="Vector3D"/> because affine maps transform
/// normals with the inverse transpose, not with the matrix itself.
/// </summary>
public struct Normal3D : ITuple3<Normal3D>
{
    public double x;
    public double y;
    public double z;

    public Normal3D(double x, double y, double z)
    {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    public Normal3D(Vector3D v) : this(v.x, v.y, v.z)
    {
    }

    public static Normal3D operator -(Normal3D n) => new(-n.x, -n.y, -n.z);
    public static Normal3D operator +(Normal3D a, Normal3D b) => new(a.x + b.x, a.y + b.y, a.z + b.z);
    public static Normal3D operator -(Normal3D a, Normal3D b) => new(a.x - b.x, a.y - b.y, a.z - b.z);
    public static Normal3D operator *(Normal3D n, double s) => new(n.x * s, n.y * s, n.z * s);
    public static Normal3D operator *(double s, Normal3D n) => new(n.x * s, n.y * s, n.z * s);
    public static Vector3D operator +(Normal3D n, Vector3D v) => new(n.x + v.x, n.y + v.y, n.z + v.z);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly double Dot(Vector3D v) => x * v.x + y * v.y + z * v.z;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly double Dot(Normal3D n) => x * n.x + y * n.y + z * n.z;

    public readonly double LengthSquared => x * x + y * y + z * z;
    public readonly double Length => Math.Sqrt(x * x + y * y + z * z);

    public readonly Normal3D Normalized()
    {
        double inv = 1.0 / Math.Sqrt(x * x + y * y + z * z);
        return new(x * inv, y * inv, z * inv);
    }

    public void Normalize()
    {
        double inv = 1.0 / Math.Sqrt(x * x + y * y + z * z);
        x *= inv;
        y *= inv;
        z *= inv;
    }

    public readonly Vector3D ToVector() => new(x, y, z);

    public static explicit operator Normal3D(Vector3D v) => new(v.x, v.y, v.z);

    static Normal3D ITuple3<Normal3D>.Create(double first, double second, double third) => new(first, second, third);

    public readonly (double First, double Second, double Third) Components => (x, y, z);

    public readonly bool Equals(Normal3D other) => Tuple3.Equal(this, other);
    public override readonly bool Equals(object? obj) => obj is Normal3D n && Equals(n);
    public override readonly int GetHashCode() => Tuple3.Hash(this);
    public static bool operator ==(Normal3D a, Normal3D b) => a.Equals(b);
    public static bool operator !=(Normal3D a, Normal3D b) => !a.Equals(b);
    public override readonly string ToString() => Tuple3.Format(this, "n(", ")");
}
