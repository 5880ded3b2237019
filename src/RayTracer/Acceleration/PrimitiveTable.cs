using System.Runtime.CompilerServices;
using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// The primitives of an acceleration structure in the order its leaves refer to them. Triangles are
/// copied into a packed array and tested inline; other objects go through their virtual
/// <see cref="GeometricObject.Intersect"/>. Unbounded objects (planes) are kept aside and tested
/// against every ray. Shadow-casting flags are read when the structure is built.
/// </summary>
internal sealed class PrimitiveTable
{
    private PackedTriangle[] _triangles;
    private bool[] _isTriangle;
    private bool[] _castsShadows;

    public PrimitiveTable(IReadOnlyList<GeometricObject> objects)
    {
        ArgumentNullException.ThrowIfNull(objects);
        var bounded = new List<GeometricObject>(objects.Count);
        var bounds = new List<BoundingBox>(objects.Count);
        var unbounded = new List<GeometricObject>();
        foreach (var o in objects)
        {
            var box = o.GetBoundingBox();
            if (box.IsEmpty)
            {
                continue; // nothing to hit
            }

            if (box.IsFinite)
            {
                bounded.Add(o);
                bounds.Add(box);
            }
            else
            {
                unbounded.Add(o);
            }
        }

        Objects = [.. bounded];
        Bounds = [.. bounds];
        Unbounded = [.. unbounded];
        Centroids = new Point3D[Objects.Length];
        _triangles = new PackedTriangle[Objects.Length];
        _isTriangle = new bool[Objects.Length];
        _castsShadows = new bool[Objects.Length];
        SceneBounds = BoundingBox.Empty;
        for (int i = 0; i < Objects.Length; i++)
        {
            Centroids[i] = Bounds[i].Centroid;
            SceneBounds.Include(Bounds[i]);
            _castsShadows[i] = Objects[i].CastsShadows;
            if (Objects[i] is ITriangle tri)
            {
                var v0 = tri.V0;
                _triangles[i] = new PackedTriangle { V0 = v0, E1 = tri.V1 - v0, E2 = tri.V2 - v0 };
                _isTriangle[i] = true;
            }
        }
    }

    public GeometricObject[] Objects { get; private set; }

    public GeometricObject[] Unbounded { get; }

    /// <summary>Per-primitive bounds; only needed while building (see <see cref="ReleaseBuildData"/>).</summary>
    public BoundingBox[] Bounds { get; private set; }

    public Point3D[] Centroids { get; private set; }

    public BoundingBox SceneBounds;

    public int Count => Objects.Length;

    public int TotalCount => Objects.Length + Unbounded.Length;

    public GeometricObject Get(int index) => index < Objects.Length ? Objects[index] : Unbounded[index - Objects.Length];

    /// <summary>Reorders the primitives so that position i holds the old primitive order[i].</summary>
    public void Permute(int[] order)
    {
        Objects = Gather(Objects, order);
        Bounds = Gather(Bounds, order);
        Centroids = Gather(Centroids, order);
        _triangles = Gather(_triangles, order);
        _isTriangle = Gather(_isTriangle, order);
        _castsShadows = Gather(_castsShadows, order);
    }

    public void ReleaseBuildData()
    {
        Bounds = [];
        Centroids = [];
    }

    /// <summary>Hit distance below tMax, or +∞.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Distance(int i, in Ray ray, double tMax)
    {
        if (_isTriangle[i])
        {
            ref var tri = ref _triangles[i];
            return TriangleSolver.Distance(ray, tri.V0, tri.E1, tri.E2, tMax);
        }

        return Objects[i].Intersect(ray, out double t) && t < tMax ? t : double.PositiveInfinity;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Occludes(int i, in Ray ray, double tMax)
    {
        if (_isTriangle[i])
        {
            if (!_castsShadows[i])
            {
                return false;
            }

            ref var tri = ref _triangles[i];
            return TriangleSolver.Intersect(ray, tri.V0, tri.E1, tri.E2, tMax, out _, out _, out _);
        }

        return Objects[i].ShadowHit(ray, out double t) && t < tMax;
    }

    /// <summary>Nearest hit among the unbounded objects, improving (t, primitive) if closer.</summary>
    public bool IntersectUnbounded(in Ray ray, ref double tBest, ref int best)
    {
        bool any = false;
        for (int j = 0; j < Unbounded.Length; j++)
        {
            if (Unbounded[j].Intersect(ray, out double t) && t < tBest)
            {
                tBest = t;
                best = Objects.Length + j;
                any = true;
            }
        }

        return any;
    }

    public bool OccludedByUnbounded(in Ray ray, double tMax)
    {
        foreach (var o in Unbounded)
        {
            if (o.ShadowHit(ray, out double t) && t < tMax)
            {
                return true;
            }
        }

        return false;
    }

    private static T[] Gather<T>(T[] source, int[] order)
    {
        if (source.Length == 0)
        {
            return source;
        }

        var result = new T[order.Length];
        for (int i = 0; i < order.Length; i++)
        {
            result[i] = source[order[i]];
        }

        return result;
    }
}
