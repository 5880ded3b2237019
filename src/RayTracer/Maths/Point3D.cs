using System.Runtime.CompilerServices;

namespace RayTracer.Maths;

/// <summary>A position in 3D space. Fields are lower-case x, y, z because generated bindings read them.</summary>
public struct Point3D : ITuple3<Point3D>
{
    public double x;
    public double y;
    public double z;

    public static readonly Point3D Origin = new(0, 0, 0);

    public Point3D(double x, double y, double z)
    {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    public Point3D(double a) : this(a, a, a)
    {
    }

    /// <summary>Component by index 0..2; used by axis-generic code in acceleration structures.</summary>
    public readonly double this[int axis]
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get => axis == 0 ? x : axis == 1 ? y : z;
    }

    public static Vector3D operator -(Point3D a, Point3D b) => new(a.x - b.x, a.y - b.y, a.z - b.z);
    public static Point3D operator +(Point3D p, Vector3D v) => new(p.x + v.x, p.y + v.y, p.z + v.z);
    public static Point3D operator -(Point3D p, Vector3D v) => new(p.x - v.x, p.y - v.y, p.z - v.z);
    public static Point3D operator *(Point3D p, double s) => new(p.x * s, p.y * s, p.z * s);
    public static Point3D operator *(double s, Point3D p) => new(p.x * s, p.y * s, p.z * s);
    public static Point3D operator -(Point3D p) => new(-p.x, -p.y, -p.z);

    public readonly double DistanceSquared(Point3D p)
    {
        double dx = x - p.x, dy = y - p.y, dz = z - p.z;
        return dx * dx + dy * dy + dz * dz;
    }

    public readonly double Distance(Point3D p) => Math.Sqrt(DistanceSquared(p));

    public static Point3D Min(Point3D a, Point3D b) => new(Math.Min(a.x, b.x), Math.Min(a.y, b.y), Math.Min(a.z, b.z));
    public static Point3D Max(Point3D a, Point3D b) => new(Math.Max(a.x, b.x), Math.Max(a.y, b.y), Math.Max(a.z, b.z));

    /// <summary>Affine combination (1 - t) a + t b.</summary>
    public static Point3D Lerp(Point3D a, Point3D b, double t) =>
        new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z));

    public readonly Vector3D ToVector() => new(x, y, z);

    static Point3D ITuple3<Point3D>.Create(double first, double second, double third) => new(first, second, third);

    public readonly (double First, double Second, double Third) Components => (x, y, z);

    public readonly bool Equals(Point3D other) => Tuple3.Equal(this, other);
    public override readonly bool Equals(object? obj) => obj is Point3D p && Equals(p);
    public override readonly int GetHashCode() => Tuple3.Hash(this);
    public static bool operator ==(Point3D a, Point3D b) => a.Equals(b);
    public static bool operator !=(Point3D a, Point3D b) => !a.Equals(b);
    public override readonly string ToString() => Tuple3.Format(this, "(", ")");
}
