using System.Runtime.CompilerServices;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Bounds;

/// <summary>An axis-aligned box [Min, Max]. Empty boxes have Min &gt; Max.</summary>
public struct BoundingBox
{
    public Point3D Min;
    public Point3D Max;

    /// <summary>Slack on the far slab distance so rounding never lets a ray slip between slabs.</summary>
    private const double FarSlack = 1.0 + 4.0 * 1.1102230246251565e-16;

    public BoundingBox(Point3D min, Point3D max)
    {
        Min = min;
        Max = max;
    }

    public BoundingBox(double x0, double x1, double y0, double y1, double z0, double z1)
        : this(new Point3D(x0, y0, z0), new Point3D(x1, y1, z1))
    {
    }

    public static BoundingBox Empty => new(
        new Point3D(double.PositiveInfinity), new Point3D(double.NegativeInfinity));

    /// <summary>Box of unbounded objects (planes); acceleration structures keep these outside.</summary>
    public static BoundingBox Infinite => new(
        new Point3D(double.NegativeInfinity), new Point3D(double.PositiveInfinity));

    public readonly bool IsEmpty => Min.x > Max.x || Min.y > Max.y || Min.z > Max.z;

    public readonly bool IsFinite =>
        double.IsFinite(Min.x) && double.IsFinite(Min.y) && double.IsFinite(Min.z) &&
        double.IsFinite(Max.x) && double.IsFinite(Max.y) && double.IsFinite(Max.z);

    public readonly Vector3D Diagonal => Max - Min;

    public readonly Point3D Centroid => new(
        0.5 * (Min.x + Max.x), 0.5 * (Min.y + Max.y), 0.5 * (Min.z + Max.z));

    public readonly double SurfaceArea
    {
        get
        {
            if (IsEmpty)
            {
                return 0;
            }

            var d = Max - Min;
            return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
        }
    }

    /// <summary>Index of the widest axis (0 = x, 1 = y, 2 = z).</summary>
    public readonly int LongestAxis
    {
        get
        {
            var d = Max - Min;
            return d.x >= d.y && d.x >= d.z ? 0 : d.y >= d.z ? 1 : 2;
        }
    }

    public static BoundingBox Union(in BoundingBox a, in BoundingBox b) =>
        new(Point3D.Min(a.Min, b.Min), Point3D.Max(a.Max, b.Max));

    public static BoundingBox Union(in BoundingBox a, Point3D p) =>
        new(Point3D.Min(a.Min, p), Point3D.Max(a.Max, p));

    public void Include(Point3D p)
    {
        Min = Point3D.Min(Min, p);
        Max = Point3D.Max(Max, p);
    }

    public void Include(in BoundingBox b)
    {
        Min = Point3D.Min(Min, b.Min);
        Max = Point3D.Max(Max, b.Max);
    }

    /// <summary>Box grown by <paramref name="delta"/> on every side.</summary>
    /// <summary>
    /// The box around the images of the eight corners under a map that keeps straight lines (affine
    /// maps, rotations, mirrors, scalings): it contains the image of the whole box. An empty box stays
    /// empty and an unbounded one becomes infinite.
    /// </summary>
    public readonly BoundingBox Map(Func<Point3D, Point3D> affine)
    {
        if (IsEmpty || !IsFinite)
            return IsEmpty ? this : Infinite;
        var result = Empty;
        for (var i = 0; i < 8; i++)
            result.Include(affine(new Point3D((i & 1) == 0 ? Min.x : Max.x, (i & 2) == 0 ? Min.y : Max.y, (i & 4) == 0 ? Min.z : Max.z)));
        return result;
    }

    public readonly BoundingBox Expanded(double delta) =>
        new(new Point3D(Min.x - delta, Min.y - delta, Min.z - delta),
            new Point3D(Max.x + delta, Max.y + delta, Max.z + delta));

    public readonly bool Contains(Point3D p) =>
        p.x >= Min.x && p.x <= Max.x && p.y >= Min.y && p.y <= Max.y && p.z >= Min.z && p.z <= Max.z;

    /// <summary>Strictly inside (Suffern's "inside" test used by the grid to pick the start cell).</summary>
    public readonly bool StrictlyContains(Point3D p) =>
        p.x > Min.x && p.x < Max.x && p.y > Min.y && p.y < Max.y && p.z > Min.z && p.z < Max.z;

    /// <summary>Slab test. Returns the parametric entry and exit distances of the line through the box.</summary>
    public readonly bool Hit(in Ray ray, out double tEnter, out double tExit)
    {
        var inv = new Vector3D(1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z);
        return Intersect(ray.o, inv, double.NegativeInfinity, double.PositiveInfinity, out tEnter, out tExit)
            && tExit > ray.tMin;
    }

    /// <summary>
    /// Allocation-free slab test with a precomputed reciprocal direction, clipped to [tMin, tMax].
    /// A zero direction component gives infinite reciprocals; the NaN from 0 * inf fails every
    /// comparison below and therefore leaves the interval unchanged, which is the right answer for
    /// a ray lying in a slab plane.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly bool Intersect(in Point3D o, in Vector3D invDir, double tMin, double tMax, out double tEnter, out double tExit)
    {
        double t0 = tMin, t1 = tMax;

        double a = (Min.x - o.x) * invDir.x, b = (Max.x - o.x) * invDir.x;
        if (a > b)
        {
            (a, b) = (b, a);
        }

        b *= FarSlack;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;

        a = (Min.y - o.y) * invDir.y;
        b = (Max.y - o.y) * invDir.y;
        if (a > b)
        {
            (a, b) = (b, a);
        }

        b *= FarSlack;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;

        a = (Min.z - o.z) * invDir.z;
        b = (Max.z - o.z) * invDir.z;
        if (a > b)
        {
            (a, b) = (b, a);
        }

        b *= FarSlack;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;

        tEnter = t0;
        tExit = t1;
        return t0 <= t1;
    }

    public override readonly string ToString() => $"[{Min} .. {Max}]";
}
