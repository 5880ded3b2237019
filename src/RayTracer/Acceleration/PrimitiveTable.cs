using System.Runtime.CompilerServices;
using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// The primitives of an acceleration structure in the order its leaves refer to them. Triangles are
/// copied into a packed array in the form their test wants (<see cref="ITriangle.Test"/>: vertex and
/// edges, three vertices, or Plücker edge lines and plane) and tested inline; an array is allocated
/// only when some triangle uses its form. Other objects go through their virtual
/// <see cref="GeometricObject.Intersect"/>. Unbounded objects (planes) are kept aside and tested
/// against every ray. Shadow-casting flags are read when the structure is built.
/// </summary>
internal sealed class PrimitiveTable
{
    private PackedTriangle[] _triangles = [];
    private PackedTriangleVertices[] _vertices = [];
    private PluckerTriangle[] _lines = [];
    private PrimitiveKind[] _kind;
    private bool[] _castsShadows;

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
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
        _kind = new PrimitiveKind[Objects.Length];
        _castsShadows = new bool[Objects.Length];
        SceneBounds = BoundingBox.Empty;
        for (int i = 0; i < Objects.Length; i++)
        {
            Centroids[i] = Bounds[i].Centroid;
            SceneBounds.Include(Bounds[i]);
            _castsShadows[i] = Objects[i].CastsShadows;
            if (Objects[i] is ITriangle tri)
                Pack(i, tri);
        }
    }

    private void Pack(int i, ITriangle tri)
    {
        Point3D v0 = tri.V0, v1 = tri.V1, v2 = tri.V2;
        switch (tri.Test)
        {
            case TriangleTest.Plucker:
                Allocate(ref _vertices)[i] = new PackedTriangleVertices { V0 = v0, V1 = v1, V2 = v2 };
                _kind[i] = PrimitiveKind.Plucker;
                break;
            case TriangleTest.PluckerEdges:
                Allocate(ref _lines)[i] = PluckerTriangle.From(v0, v1, v2);
                _kind[i] = PrimitiveKind.PluckerEdges;
                break;
            default:
                Allocate(ref _triangles)[i] = new PackedTriangle { V0 = v0, E1 = v1 - v0, E2 = v2 - v0 };
                _kind[i] = tri.Test == TriangleTest.Algebraic ? PrimitiveKind.Algebraic : PrimitiveKind.MollerTrumbore;
                break;
        }
    }

    private T[] Allocate<T>(ref T[] array)
    {
        if (array.Length == 0)
            array = new T[Objects.Length];
        return array;
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
        _vertices = Gather(_vertices, order);
        _lines = Gather(_lines, order);
        _kind = Gather(_kind, order);
        _castsShadows = Gather(_castsShadows, order);
    }

    /// <summary>Whether primitive i is a triangle tested with Möller–Trumbore, so it can join a four-lane group.</summary>
    public bool IsMollerTrumbore(int i) => _kind[i] == PrimitiveKind.MollerTrumbore;

    /// <summary>The packed form of a triangle for which <see cref="IsMollerTrumbore"/> holds.</summary>
    public ref readonly PackedTriangle Packed(int i) => ref _triangles[i];

    public bool CastsShadows(int i) => _castsShadows[i];

    public void ReleaseBuildData()
    {
        Bounds = [];
        Centroids = [];
    }

    /// <summary>Hit distance below tMax, or +∞.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Distance(int i, in Ray ray, double tMax)
    {
        switch (_kind[i])
        {
            case PrimitiveKind.MollerTrumbore:
            {
                ref var tri = ref _triangles[i];
                return TriangleSolver.Distance(ray, tri.V0, tri.E1, tri.E2, tMax);
            }
            case PrimitiveKind.Algebraic:
            {
                ref var tri = ref _triangles[i];
                return AlgebraicTriangleSolver.Distance(ray, tri.V0, tri.E1, tri.E2, tMax);
            }
            case PrimitiveKind.Plucker:
            {
                ref var tri = ref _vertices[i];
                return PluckerTriangleSolver.Distance(ray, tri.V0, tri.V1, tri.V2, tMax);
            }
            case PrimitiveKind.PluckerEdges:
                return PluckerTriangleSolver.Distance(ray, PluckerTriangleSolver.RayLine(ray), _lines[i], tMax);
            default:
                return Objects[i].Intersect(ray, out double t) && t < tMax ? t : double.PositiveInfinity;
        }
    }

    /// <summary>As <see cref="Distance(int, in Ray, double)"/>, with the ray's Plücker line built once per ray by the caller.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Distance(int i, in Ray ray, in PluckerLine rayLine, double tMax) =>
        _kind[i] == PrimitiveKind.PluckerEdges
            ? PluckerTriangleSolver.Distance(ray, rayLine, _lines[i], tMax)
            : Distance(i, ray, tMax);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Occludes(int i, in Ray ray, in PluckerLine rayLine, double tMax) =>
        _kind[i] == PrimitiveKind.PluckerEdges
            ? _castsShadows[i] && PluckerTriangleSolver.Distance(ray, rayLine, _lines[i], tMax) < tMax
            : Occludes(i, ray, tMax);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Occludes(int i, in Ray ray, double tMax)
    {
        var kind = _kind[i];
        if (kind == PrimitiveKind.Object)
            return Objects[i].ShadowHit(ray, out double t) && t < tMax;

        return _castsShadows[i] && Distance(i, ray, tMax) < tMax;
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

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static T[] Gather<T>(T[] source, int[] order)
    {
        if (source.Length == 0)
        {
            return source;
        }

        var result = new T[order.Length];
        const int PerTask = 1 << 16;
        ChunkedLoop.For(order.Length, PerTask, (start, end) =>
        {
            for (int i = start; i < end; i++)
                result[i] = source[order[i]];
        });
        return result;
    }
}
