using System.Runtime.CompilerServices;

namespace RayTracer.Maths;

/// <summary>A direction or displacement in 3D space.</summary>
public struct Vector3D : ITuple3<Vector3D>
{
    public double x;
    public double y;
    public double z;

    public static readonly Vector3D Zero = new(0, 0, 0);
    public static readonly Vector3D UnitX = new(1, 0, 0);
    public static readonly Vector3D UnitY = new(0, 1, 0);
    public static readonly Vector3D UnitZ = new(0, 0, 1);

    public Vector3D(double x, double y, double z)
    {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    public Vector3D(double a) : this(a, a, a)
    {
    }

    public readonly double this[int axis]
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get => axis == 0 ? x : axis == 1 ? y : z;
    }

    public static Vector3D operator +(Vector3D a, Vector3D b) => new(a.x + b.x, a.y + b.y, a.z + b.z);
    public static Vector3D operator -(Vector3D a, Vector3D b) => new(a.x - b.x, a.y - b.y, a.z - b.z);
    public static Vector3D operator -(Vector3D a) => new(-a.x, -a.y, -a.z);
    public static Vector3D operator *(Vector3D a, double s) => new(a.x * s, a.y * s, a.z * s);
    public static Vector3D operator *(double s, Vector3D a) => new(a.x * s, a.y * s, a.z * s);
    public static Vector3D operator /(Vector3D a, double s)
    {
        double inv = 1.0 / s;
        return new(a.x * inv, a.y * inv, a.z * inv);
    }

    public static Vector3D operator +(Vector3D a, Normal3D n) => new(a.x + n.x, a.y + n.y, a.z + n.z);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Dot(Vector3D a, Vector3D b) => a.x * b.x + a.y * b.y + a.z * b.z;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Dot(Vector3D a, Normal3D n) => a.x * n.x + a.y * n.y + a.z * n.z;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Cross(Vector3D a, Vector3D b) =>
        new(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);

    public readonly double Dot(Vector3D b) => Dot(this, b);
    public readonly double Dot(Normal3D n) => Dot(this, n);
    public readonly Vector3D Cross(Vector3D b) => Cross(this, b);

    public readonly double LengthSquared => x * x + y * y + z * z;
    public readonly double Length => Math.Sqrt(x * x + y * y + z * z);

    /// <summary>Unit vector with the same direction (the "hat" of Suffern's code).</summary>
    public readonly Vector3D Normalized()
    {
        double inv = 1.0 / Math.Sqrt(x * x + y * y + z * z);
        return new(x * inv, y * inv, z * inv);
    }

    /// <summary>Normalizes in place.</summary>
    public void Normalize()
    {
        double inv = 1.0 / Math.Sqrt(x * x + y * y + z * z);
        x *= inv;
        y *= inv;
        z *= inv;
    }

    public static explicit operator Vector3D(Normal3D n) => new(n.x, n.y, n.z);
    public static explicit operator Vector3D(Point3D p) => new(p.x, p.y, p.z);

    static Vector3D ITuple3<Vector3D>.Create(double first, double second, double third) => new(first, second, third);

    public readonly (double First, double Second, double Third) Components => (x, y, z);

    public readonly bool Equals(Vector3D other) => Tuple3.Equal(this, other);
    public override readonly bool Equals(object? obj) => obj is Vector3D v && Equals(v);
    public override readonly int GetHashCode() => Tuple3.Hash(this);
    public static bool operator ==(Vector3D a, Vector3D b) => a.Equals(b);
    public static bool operator !=(Vector3D a, Vector3D b) => !a.Equals(b);
    public override readonly string ToString() => Tuple3.Format(this, "[", "]");
}
