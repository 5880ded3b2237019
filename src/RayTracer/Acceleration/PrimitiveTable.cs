using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
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
/// only when some triangle uses its form, and only when the structure asks (<see cref="PackTriangles"/>),
/// so a structure with its own copy of the triangles does not pay for a second. Other objects go through their virtual
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
    private Point3D[]? _centroids;

    /// <summary>Objects per work item of the parallel passes over all of them.</summary>
    private const int ChunkSize = 1 << 14;

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public PrimitiveTable(IReadOnlyList<GeometricObject> objects)
    {
        ArgumentNullException.ThrowIfNull(objects);
        var source = objects as GeometricObject[] ?? [.. objects];
        int n = source.Length;

        // One pass in parallel chunks: each object's box, kind and shadow flag, and the scene's box. Mesh
        // triangles, by far the most common, are recognized by their (sealed) type and read without a
        // virtual or interface call. The objects are sorted into bounded and unbounded ones only when
        // some box is empty or infinite.
        var boxes = GC.AllocateUninitializedArray<BoundingBox>(n);
        var kinds = GC.AllocateUninitializedArray<PrimitiveKind>(n);
        var shadows = GC.AllocateUninitializedArray<bool>(n);
        int unusual = 0;
        var sceneBounds = BoundingBox.Empty;
        var gate = new object();
        ChunkedLoop.For(n, ChunkSize, [MethodImpl(MethodImplOptions.AggressiveOptimization)] (start, end) =>
        {
            bool any = false;
            // Componentwise, so that nothing here waits for tiered compilation.
            double x0 = double.PositiveInfinity, y0 = x0, z0 = x0, x1 = double.NegativeInfinity, y1 = x1, z1 = x1;
            for (int i = start; i < end; i++)
            {
                var o = source[i];
                BoundingBox b;
                if (o is MeshTriangle triangle)
                {
                    b = triangle.GetBoundingBox();
                    shadows[i] = triangle.CastsShadows;
                    kinds[i] = KindOf(triangle.Test);
                }
                else
                {
                    b = o.GetBoundingBox();
                    shadows[i] = o.CastsShadows;
                    kinds[i] = o is ITriangle tri ? KindOf(tri.Test) : PrimitiveKind.Object;
                }

                boxes[i] = b;
                any |= b.IsEmpty || !b.IsFinite;
                x0 = Math.Min(x0, b.Min.x);
                y0 = Math.Min(y0, b.Min.y);
                z0 = Math.Min(z0, b.Min.z);
                x1 = Math.Max(x1, b.Max.x);
                y1 = Math.Max(y1, b.Max.y);
                z1 = Math.Max(z1, b.Max.z);
            }

            if (any)
                Volatile.Write(ref unusual, 1);
            lock (gate)
                sceneBounds.Include(new BoundingBox(new Point3D(x0, y0, z0), new Point3D(x1, y1, z1)));
        });

        if (unusual == 0)
        {
            Objects = ReferenceEquals(source, objects) ? [.. source] : source;
            Bounds = boxes;
            Unbounded = [];
            _kind = kinds;
            _castsShadows = shadows;
            SceneBounds = sceneBounds;
            return;
        }

        var bounded = new List<int>(n);
        var unbounded = new List<GeometricObject>();
        sceneBounds = BoundingBox.Empty;
        for (int i = 0; i < n; i++)
        {
            if (boxes[i].IsEmpty)
                continue; // nothing to hit
            if (boxes[i].IsFinite)
            {
                bounded.Add(i);
                sceneBounds.Include(boxes[i]);
            }
            else
            {
                unbounded.Add(source[i]);
            }
        }

        Objects = [.. bounded.Select(i => source[i])];
        Bounds = [.. bounded.Select(i => boxes[i])];
        _kind = [.. bounded.Select(i => kinds[i])];
        _castsShadows = [.. bounded.Select(i => shadows[i])];
        Unbounded = [.. unbounded];
        SceneBounds = sceneBounds;
    }

    /// <summary>
    /// Copies the triangles into the packed arrays their tests read, in the current order; a structure
    /// calls it once its order is final (after <see cref="Permute"/>) and only when it tests primitives
    /// through <see cref="Distance(int, in Ray, double)"/> or <see cref="Occludes(int, in Ray, double)"/>.
    /// </summary>
    public void PackTriangles()
    {
        int n = Objects.Length;
        bool plucker = false, edges = false, triangles = false;
        foreach (var kind in _kind)
        {
            plucker |= kind == PrimitiveKind.Plucker;
            edges |= kind == PrimitiveKind.PluckerEdges;
            triangles |= kind is PrimitiveKind.MollerTrumbore or PrimitiveKind.Algebraic;
        }

        _vertices = plucker ? new PackedTriangleVertices[n] : [];
        _lines = edges ? new PluckerTriangle[n] : [];
        _triangles = triangles ? new PackedTriangle[n] : [];
        if (plucker || edges || triangles)
        {
            ChunkedLoop.For(n, ChunkSize, [MethodImpl(MethodImplOptions.AggressiveOptimization)] (start, end) =>
            {
                for (int i = start; i < end; i++)
                {
                    if (_kind[i] != PrimitiveKind.Object)
                        Pack(i, (ITriangle)Objects[i]);
                }
            });
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static PrimitiveKind KindOf(TriangleTest test) => test switch
    {
        TriangleTest.Plucker => PrimitiveKind.Plucker,
        TriangleTest.PluckerEdges => PrimitiveKind.PluckerEdges,
        TriangleTest.Algebraic => PrimitiveKind.Algebraic,
        _ => PrimitiveKind.MollerTrumbore,
    };

    private void Pack(int i, ITriangle tri)
    {
        Point3D v0 = tri.V0, v1 = tri.V1, v2 = tri.V2;
        switch (_kind[i])
        {
            case PrimitiveKind.Plucker:
                _vertices[i] = new PackedTriangleVertices { V0 = v0, V1 = v1, V2 = v2 };
                break;
            case PrimitiveKind.PluckerEdges:
                _lines[i] = PluckerTriangle.From(v0, v1, v2);
                break;
            default:
                _triangles[i] = PackedTriangle.From(v0, v1, v2);
                break;
        }
    }

    public GeometricObject[] Objects { get; private set; }

    public GeometricObject[] Unbounded { get; }

    /// <summary>Per-primitive bounds; only needed while building (see <see cref="ReleaseBuildData"/>).</summary>
    public BoundingBox[] Bounds { get; private set; }

    /// <summary>Centres of <see cref="Bounds"/>, computed when first asked for.</summary>
    public Point3D[] Centroids
    {
        get
        {
            if (_centroids is null)
            {
                _centroids = new Point3D[Bounds.Length];
                for (int i = 0; i < _centroids.Length; i++)
                    _centroids[i] = Bounds[i].Centroid;
            }

            return _centroids;
        }
    }

    public BoundingBox SceneBounds;

    public int Count => Objects.Length;

    public int TotalCount => Objects.Length + Unbounded.Length;

    public GeometricObject Get(int index) => index < Objects.Length ? Objects[index] : Unbounded[index - Objects.Length];

    /// <summary>Reorders the primitives so that position i holds the old primitive order[i].</summary>
    public void Permute(int[] order)
    {
        Objects = Gather(Objects, order);
        Bounds = Gather(Bounds, order);
        _centroids = _centroids is null ? null : Gather(_centroids, order);
        _triangles = Gather(_triangles, order);
        _vertices = Gather(_vertices, order);
        _lines = Gather(_lines, order);
        _kind = Gather(_kind, order);
        _castsShadows = Gather(_castsShadows, order);
    }

    /// <summary>Whether primitive i is a triangle tested with Möller–Trumbore, so it can join a four-lane group.</summary>
    public bool IsMollerTrumbore(int i) => _kind[i] == PrimitiveKind.MollerTrumbore;

    /// <summary>The Möller–Trumbore form of a triangle for which <see cref="IsMollerTrumbore"/> holds, computed from the object.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public PackedTriangle MollerTrumbore(int i)
    {
        // Mesh triangles, by far the most common, without the interface calls.
        if (Objects[i] is MeshTriangle mesh)
            return PackedTriangle.From(mesh.V0, mesh.V1, mesh.V2);
        var tri = (ITriangle)Objects[i];
        return PackedTriangle.From(tri.V0, tri.V1, tri.V2);
    }

    public bool CastsShadows(int i) => _castsShadows[i];

    public void ReleaseBuildData()
    {
        Bounds = [];
        _centroids = [];
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

        var result = GC.AllocateUninitializedArray<T>(order.Length);
        const int PerTask = 1 << 16;
        ChunkedLoop.For(order.Length, PerTask, [MethodImpl(MethodImplOptions.AggressiveOptimization)] (start, end) =>
        {
            // Through a reference, which skips the array-covariance check of each element store.
            ref var first = ref MemoryMarshal.GetArrayDataReference(result);
            for (int i = start; i < end; i++)
                Unsafe.Add(ref first, i) = source[order[i]];
        });
        return result;
    }
}
