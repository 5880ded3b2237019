using RayTracer.Bounds;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Csg;

/// <summary>
/// Union, intersection or difference of two closed solids (constructive solid geometry). Any closed
/// object works as an operand (spheres, boxes, tori, solid compounds, instances of them, closed
/// meshes, other constructive solids): all surface crossings along the ray are found by repeated
/// nearest-hit queries, whether the ray starts inside an operand follows from the parity of its
/// crossings, and the first crossing where the combined inside/outside state changes is the hit.
/// Surfaces of the subtracted solid keep their shape but their normals are reversed.
/// </summary>
public sealed class ConstructiveSolid : GeometricObject
{
    // Crossings examined per operand; enough for any practical solid, bounded for safety.
    private const int MaxCrossings = 32;

    public ConstructiveSolid(SolidOperation operation, GeometricObject left, GeometricObject right)
    {
        Operation = operation;
        Left = left ?? throw new ArgumentNullException(nameof(left));
        Right = right ?? throw new ArgumentNullException(nameof(right));
    }

    public SolidOperation Operation { get; }

    public GeometricObject Left { get; }

    public GeometricObject Right { get; }

    public override bool Intersect(in Ray ray, out double t) => Solve(ray, out t, null);

    public override bool Hit(in Ray ray, out double tmin, ShadingRecord sr) => Solve(ray, out tmin, sr);

    public override BoundingBox GetBoundingBox()
    {
        BoundingBox a = Left.GetBoundingBox(), b = Right.GetBoundingBox();
        return Operation switch
        {
            SolidOperation.Union => BoundingBox.Union(a, b),
            SolidOperation.Intersection => new BoundingBox(Point3D.Max(a.Min, b.Min), Point3D.Min(a.Max, b.Max)),
            _ => a,
        };
    }

    private bool Combine(bool inLeft, bool inRight) => Operation switch
    {
        SolidOperation.Union => inLeft || inRight,
        SolidOperation.Intersection => inLeft && inRight,
        _ => inLeft && !inRight,
    };

    private bool Solve(in Ray ray, out double tmin, ShadingRecord? sr)
    {
        tmin = 0;
        double length = ray.d.Length;
        if (!(length > 0))
        {
            return false;
        }

        // March with a unit direction; t, and the nearest t accepted, scale with it.
        var unit = new Ray(ray.o, ray.d / length, ray.tMin * length);
        Span<double> leftT = stackalloc double[MaxCrossings], leftFrom = stackalloc double[MaxCrossings];
        Span<double> rightT = stackalloc double[MaxCrossings], rightFrom = stackalloc double[MaxCrossings];
        int nl = Crossings(Left, unit, leftT, leftFrom);
        int nr = Crossings(Right, unit, rightT, rightFrom);

        // An odd number of crossings ahead means the ray starts inside a closed solid.
        bool inLeft = (nl & 1) == 1, inRight = (nr & 1) == 1;
        bool inside = Combine(inLeft, inRight);
        int i = 0, j = 0;
        while (i < nl || j < nr)
        {
            bool takeLeft = j >= nr || (i < nl && leftT[i] <= rightT[j]);
            if (takeLeft)
            {
                inLeft = !inLeft;
            }
            else
            {
                inRight = !inRight;
            }

            bool now = Combine(inLeft, inRight);
            if (now != inside)
            {
                var part = takeLeft ? Left : Right;
                double t = takeLeft ? leftT[i] : rightT[j];
                double from = takeLeft ? leftFrom[i] : rightFrom[j];
                tmin = t / length;
                if (sr is not null)
                {
                    // Repeat the query that found this crossing to get its shading data.
                    if (!part.Hit(new Ray(unit.At(from), unit.d, unit.tMin), out _, sr))
                    {
                        return false;
                    }

                    if (!takeLeft && Operation == SolidOperation.Difference)
                    {
                        sr.Normal = -sr.Normal;
                    }

                    if (Material is not null)
                    {
                        sr.Material = Material;
                    }
                }

                return true;
            }

            if (takeLeft)
            {
                i++;
            }
            else
            {
                j++;
            }
        }

        return false;
    }

    /// <summary>All crossings of the ray with <paramref name="solid"/>, ascending, with the start of the query that found each.</summary>
    private static int Crossings(GeometricObject solid, in Ray ray, Span<double> t, Span<double> from)
    {
        int n = 0;
        double start = 0;
        while (n < t.Length && solid.Intersect(new Ray(ray.At(start), ray.d, ray.tMin), out double dt))
        {
            from[n] = start;
            start += dt;
            t[n++] = start;
        }

        return n;
    }
}
