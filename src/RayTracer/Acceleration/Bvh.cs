using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Bounding volume hierarchy built top-down with the binned surface area heuristic (see
/// <see cref="BvhBuilder"/>), then collapsed into four-wide nodes whose child boxes are tested together
/// with vector instructions; leaves of triangles test four of them at once
/// (<see cref="TriangleGroupSolver"/>). Traversal uses a fixed stack on the call stack (no allocation),
/// visits entered children nearest first and skips subtrees that start beyond the best hit so far.
/// </summary>
public sealed class Bvh : AccelerationStructure
{
    private const int MaxDepth = 60;

    // Each wide level pushes at most three entries beyond the one it pops.
    private const int StackSize = 3 * MaxDepth + 8;

    // Slack on far slab distances and on the best distance a subtree's entry is compared with: 1 + 2⁻²⁰.
    // The box test rounds (pbrt's 1 + 2γ₃ would cover that), and so does the triangle test: the distance it
    // computes for a hit on a box face can lie a few units in the last place below the box's computed
    // entry (seen at coordinates near 1e30 and 1e-30), and a node must not be skipped for that.
    private const double FarSlack = 1.0 + 1.0 / (1 << 20);

    // Slack for the far distance of the vector slab test; see WideRay.
    private static readonly Vector256<double> FarSlackVector = Vector256.Create(FarSlack);

    // Nodes start on a cache line: a node is then exactly two lines.
    private const int NodeAlignment = 64;

    private readonly BvhNode[] _nodes;

    // Pinned (it never moves), one node longer than needed; node 0 is _wideOffset bytes into it, on a cache line.
    private readonly Bvh4Node[] _wide = [];
    private readonly int _wideOffset;
    private readonly BvhLeaf[] _leaves = [];
    private readonly TriangleGroup4[] _groups = [];
    private int _wideCount;
    private int _leafCount;

    public Bvh(IReadOnlyList<GeometricObject> objects, int maxLeafSize = 4)
        : this(objects, maxLeafSize, BvhBuilder.Parallelism.Default)
    {
    }

    /// <summary>As the public constructor, with the sizes from which the build shares work among threads.</summary>
    internal Bvh(IReadOnlyList<GeometricObject> objects, int maxLeafSize, BvhBuilder.Parallelism parallelism)
        : base(objects)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxLeafSize, 1);
        MaxLeafSize = maxLeafSize;
        int n = Table.Count;
        if (n == 0)
        {
            _nodes = [];
            return;
        }

        _nodes = BvhBuilder.Build(Table.Bounds, maxLeafSize, MaxDepth, parallelism, out var order, out int binaryNodes);
        Table.ReleaseBuildData();

        // The table is put in build order while this thread collapses pairs of levels into four-wide
        // nodes for traversal (the collapse reads only the binary nodes). A full binary tree of m nodes has
        // (m + 1) / 2 leaves, which stay leaves, and (m - 1) / 2 interior nodes, at least two per wide
        // node but the root; the wide array may be longer than its count, and its tail is never touched.
        var permute = parallelism.Chunk < n ? Task.Run(() => Table.Permute(order)) : null;
        if (permute is null)
            Table.Permute(order);
        _wide = GC.AllocateUninitializedArray<Bvh4Node>(Math.Max(1, (binaryNodes - 1) / 2) + 1, pinned: true);
        long address = Marshal.UnsafeAddrOfPinnedArrayElement(_wide, 0);
        _wideOffset = (int)((NodeAlignment - (address & (NodeAlignment - 1))) & (NodeAlignment - 1));
        _leaves = GC.AllocateUninitializedArray<BvhLeaf>((binaryNodes + 1) / 2);
        Collapse(0);
        permute?.Wait();
        int groupCount = DescribeLeaves(_leaves, out bool oneByOne);
        _groups = FillGroups(_leaves, groupCount, Math.Max(1, parallelism.Chunk / 256));
        if (oneByOne)
            Table.PackTriangles(); // some leaves test their primitives one by one
        BinaryNodeCount = binaryNodes;
        _nodes = [];
    }

    public int MaxLeafSize { get; }

    /// <summary>Nodes of the binary SAH tree that was built.</summary>
    public int BinaryNodeCount { get; }

    /// <summary>Nodes of the four-wide tree used for traversal.</summary>
    public int NodeCount => _wideCount;

    /// <summary>Wide node 0, on a cache line; node i is <c>Unsafe.Add(ref root, i)</c>.</summary>
    private ref Bvh4Node WideRoot
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get => ref Unsafe.AddByteOffset(ref MemoryMarshal.GetArrayDataReference(_wide), (nint)_wideOffset);
    }

    [SkipLocalsInit]
    private protected override bool TraverseNearest(in Ray ray, ref double t, ref int primitive)
    {
        if (_wide.Length == 0)
        {
            return false;
        }

        var r = new WideRay(ray);
        ref var nodes = ref WideRoot;
        var leaves = _leaves;
        var groups = _groups;
        var lanes = new TriangleGroupSolver.RayLanes(ray);
        var table = Table;
        Span<int> stackRef = stackalloc int[StackSize];
        Span<double> stackEnter = stackalloc double[StackSize];
        int sp = 0;
        bool hit = false;
        int current = 0;

        while (true)
        {
            ref var node = ref Unsafe.Add(ref nodes, current);
            int mask = r.Hits(ref node, t, out var enter);

            // A single interior child needs no trip through the stack.
            if (mask != 0 && (mask & (mask - 1)) == 0)
            {
                int lane = BitOperations.TrailingZeroCount(mask);
                int only = lane switch { 0 => node.Child0, 1 => node.Child1, 2 => node.Child2, _ => node.Child3 };
                if (only >= 0)
                {
                    current = only;
                    continue;
                }
            }

            // Push the children that the ray enters, farthest first, so the nearest is popped next.
            int pushedFrom = sp;
            while (mask != 0)
            {
                int lane = BitOperations.TrailingZeroCount(mask);
                mask &= mask - 1;
                int child = lane switch { 0 => node.Child0, 1 => node.Child1, 2 => node.Child2, _ => node.Child3 };
                double te = enter.GetElement(lane);
                int j = sp++;
                while (j > pushedFrom && stackEnter[j - 1] < te)
                {
                    stackEnter[j] = stackEnter[j - 1];
                    stackRef[j] = stackRef[j - 1];
                    j--;
                }

                stackEnter[j] = te;
                stackRef[j] = child;
            }

            // Pop until an interior node to descend into is found, testing leaves on the way.
            while (true)
            {
                if (sp == 0)
                {
                    return hit;
                }

                sp--;
                if (stackEnter[sp] > t * FarSlack)
                {
                    continue;
                }

                int reference = stackRef[sp];
                if (reference >= 0)
                {
                    current = reference;
                    break;
                }

                ref var leaf = ref leaves[~reference];
                if (leaf.Group >= 0)
                {
                    for (int g = 0; g < leaf.GroupCount; g++)
                    {
                        var tMax = Vector256.Create(t);
                        var tv = TriangleGroupSolver.Distances(lanes, ref groups[leaf.Group + g], tMax);
                        int found = (int)Vector256.LessThan(tv, tMax).ExtractMostSignificantBits();
                        while (found != 0)
                        {
                            // Lanes in index order with a strict test: ties go to the lower index, as in the scalar loop.
                            int lane = BitOperations.TrailingZeroCount(found);
                            found &= found - 1;
                            double ti = tv.GetElement(lane);
                            if (ti < t)
                            {
                                t = ti;
                                primitive = leaf.First + 4 * g + lane;
                                hit = true;
                            }
                        }
                    }

                    continue;
                }

                for (int i = leaf.First, end = leaf.First + leaf.Count; i < end; i++)
                {
                    double ti = table.Distance(i, ray, t);
                    if (ti < t)
                    {
                        t = ti;
                        primitive = i;
                        hit = true;
                    }
                }
            }
        }
    }

    [SkipLocalsInit]
    private protected override bool TraverseAny(in Ray ray, double tMax)
    {
        if (_wide.Length == 0)
        {
            return false;
        }

        var r = new WideRay(ray);
        ref var nodes = ref WideRoot;
        var leaves = _leaves;
        var groups = _groups;
        var lanes = new TriangleGroupSolver.RayLanes(ray);
        var table = Table;
        var tMaxLanes = Vector256.Create(tMax);
        Span<int> stackRef = stackalloc int[StackSize];
        int sp = 0;
        stackRef[sp++] = 0;

        while (sp > 0)
        {
            int reference = stackRef[--sp];
            if (reference < 0)
            {
                ref var leaf = ref leaves[~reference];
                if (leaf.Group >= 0 && leaf.GroupsCastShadows)
                {
                    for (int g = 0; g < leaf.GroupCount; g++)
                    {
                        if (Vector256.LessThanAny(TriangleGroupSolver.Distances(lanes, ref groups[leaf.Group + g], tMaxLanes), tMaxLanes))
                        {
                            return true;
                        }
                    }

                    continue;
                }

                for (int i = leaf.First, end = leaf.First + leaf.Count; i < end; i++)
                {
                    if (table.Occludes(i, ray, tMax))
                    {
                        return true;
                    }
                }

                continue;
            }

            ref var node = ref Unsafe.Add(ref nodes, reference);
            int mask = r.Hits(ref node, tMax, out _);
            while (mask != 0)
            {
                int lane = BitOperations.TrailingZeroCount(mask);
                mask &= mask - 1;
                stackRef[sp++] = lane switch { 0 => node.Child0, 1 => node.Child1, 2 => node.Child2, _ => node.Child3 };
            }
        }

        return false;
    }

    /// <summary>
    /// The leaves, each with its run of four-lane groups when all its primitives are Möller–Trumbore
    /// triangles; returns the number of groups. <paramref name="oneByOne"/> tells whether some leaf tests its
    /// primitives one by one (in one query or both), which needs the table's packed triangles.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int DescribeLeaves(BvhLeaf[] leaves, out bool oneByOne)
    {
        int groupCount = 0;
        oneByOne = false;
        for (int l = 0; l < leaves.Length; l++)
        {
            int first = leaves[l].First, count = leaves[l].Count;
            leaves[l].Group = -1;
            leaves[l].GroupCount = 0;
            leaves[l].GroupsCastShadows = false;
            bool triangles = true, castShadows = true;
            for (int i = first; i < first + count; i++)
            {
                triangles &= Table.IsMollerTrumbore(i);
                castShadows &= Table.CastsShadows(i);
            }

            if (triangles)
            {
                leaves[l].Group = groupCount;
                leaves[l].GroupCount = (count + 3) / 4;
                leaves[l].GroupsCastShadows = castShadows;
                groupCount += leaves[l].GroupCount;
            }

            oneByOne |= !(triangles && castShadows);
        }

        return groupCount;
    }

    /// <summary>Copies the leaves' triangles into their groups, four lanes at a time; lanes left over are zero and never hit.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private TriangleGroup4[] FillGroups(BvhLeaf[] leaves, int groupCount, int leavesPerTask)
    {
        var groups = GC.AllocateUninitializedArray<TriangleGroup4>(groupCount);
        ChunkedLoop.For(leaves.Length, leavesPerTask, [MethodImpl(MethodImplOptions.AggressiveOptimization)] (start, end) =>
        {
            for (int l = start; l < end; l++)
            {
                var leaf = leaves[l];
                for (int g = 0; g < leaf.GroupCount; g++)
                {
                    int first = leaf.First + 4 * g, lanes = Math.Min(4, leaf.Count - 4 * g);
                    var a = Table.MollerTrumbore(first);
                    var b = lanes > 1 ? Table.MollerTrumbore(first + 1) : default;
                    var c = lanes > 2 ? Table.MollerTrumbore(first + 2) : default;
                    var d = lanes > 3 ? Table.MollerTrumbore(first + 3) : default;
                    groups[leaf.Group + g] = new TriangleGroup4
                    {
                        V0 = Lanes(a.V0.x, b.V0.x, c.V0.x, d.V0.x, a.V0.y, b.V0.y, c.V0.y, d.V0.y, a.V0.z, b.V0.z, c.V0.z, d.V0.z),
                        E1 = Lanes(a.E1.x, b.E1.x, c.E1.x, d.E1.x, a.E1.y, b.E1.y, c.E1.y, d.E1.y, a.E1.z, b.E1.z, c.E1.z, d.E1.z),
                        E2 = Lanes(a.E2.x, b.E2.x, c.E2.x, d.E2.x, a.E2.y, b.E2.y, c.E2.y, d.E2.y, a.E2.z, b.E2.z, c.E2.z, d.E2.z),
                    };
                }
            }
        });
        return groups;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector3x4 Lanes(double x0, double x1, double x2, double x3, double y0, double y1, double y2, double y3, double z0, double z1, double z2, double z3) =>
        new() { x = Vector256.Create(x0, x1, x2, x3), y = Vector256.Create(y0, y1, y2, y3), z = Vector256.Create(z0, z1, z2, z3) };

    /// <summary>
    /// Turns the binary subtree at <paramref name="binary"/> into a four-wide node: its children are
    /// opened, largest surface area first, until there are four slots or only leaves remain.
    /// </summary>
    [SkipLocalsInit]
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Collapse(int binary)
    {
        Span<int> slots = stackalloc int[4];
        int count = 0;
        var root = _nodes[binary];
        if (root.Count > 0)
        {
            slots[count++] = binary;
        }
        else
        {
            slots[count++] = root.Offset;
            slots[count++] = root.Offset + 1;
            while (count < 4)
            {
                int best = -1;
                double bestArea = -1;
                for (int i = 0; i < count; i++)
                {
                    var c = _nodes[slots[i]];
                    if (c.Count == 0 && c.SurfaceArea > bestArea)
                    {
                        bestArea = c.SurfaceArea;
                        best = i;
                    }
                }

                if (best < 0)
                {
                    break;
                }

                int opened = slots[best];
                slots[best] = _nodes[opened].Offset;
                slots[count++] = _nodes[opened].Offset + 1;
            }
        }

        int index = _wideCount++;
        Span<float> minX = stackalloc float[4], minY = stackalloc float[4], minZ = stackalloc float[4];
        Span<float> maxX = stackalloc float[4], maxY = stackalloc float[4], maxZ = stackalloc float[4];
        Span<int> refs = stackalloc int[4];
        for (int i = 0; i < 4; i++)
        {
            if (i >= count)
            {
                minX[i] = minY[i] = minZ[i] = maxX[i] = maxY[i] = maxZ[i] = 0;
                refs[i] = 0;
                continue;
            }

            var c = _nodes[slots[i]];
            minX[i] = c.Min.GetElement(0);
            minY[i] = c.Min.GetElement(1);
            minZ[i] = c.Min.GetElement(2);
            maxX[i] = c.Max.GetElement(0);
            maxY[i] = c.Max.GetElement(1);
            maxZ[i] = c.Max.GetElement(2);
            if (c.Count > 0)
            {
                refs[i] = ~_leafCount;
                _leaves[_leafCount++] = new BvhLeaf { First = c.Offset, Count = c.Count };
            }
            else
            {
                refs[i] = Collapse(slots[i]);
            }
        }

        Unsafe.Add(ref WideRoot, index) = new Bvh4Node
        {
            MinX = Vector128.Create(minX[0], minX[1], minX[2], minX[3]),
            MinY = Vector128.Create(minY[0], minY[1], minY[2], minY[3]),
            MinZ = Vector128.Create(minZ[0], minZ[1], minZ[2], minZ[3]),
            MaxX = Vector128.Create(maxX[0], maxX[1], maxX[2], maxX[3]),
            MaxY = Vector128.Create(maxY[0], maxY[1], maxY[2], maxY[3]),
            MaxZ = Vector128.Create(maxZ[0], maxZ[1], maxZ[2], maxZ[3]),
            Child0 = refs[0],
            Child1 = refs[1],
            Child2 = refs[2],
            Child3 = refs[3],
            ValidMask = (1 << count) - 1,
        };
        return index;
    }

    /// <summary>
    /// Ray broadcast into vectors for testing four boxes at once. The single-precision planes are widened
    /// to double (exactly) as they are loaded, so the test computes in double precision what it computed
    /// when the nodes held doubles, bit for bit: the rays visit the same nodes in the same order.
    /// </summary>
    private readonly struct WideRay
    {
        private readonly Vector256<double> _ox, _oy, _oz, _ix, _iy, _iz;

        // The origin for the far planes: the origin, but moved off it on an axis the ray does not move along.
        private readonly Vector256<double> _fx, _fy, _fz;

        // Plane indices in a node (0–2 the minimum corner's x, y, z, 3–5 the maximum's): on each axis the ray
        // enters a slab through the minimum plane when its direction is positive, else through the maximum.
        private readonly int _nearX, _nearY, _nearZ;

        public WideRay(in Ray ray)
        {
            _ox = Vector256.Create(ray.o.x);
            _oy = Vector256.Create(ray.o.y);
            _oz = Vector256.Create(ray.o.z);
            _fx = Vector256.Create(FarOrigin(ray.o.x, ray.d.x));
            _fy = Vector256.Create(FarOrigin(ray.o.y, ray.d.y));
            _fz = Vector256.Create(FarOrigin(ray.o.z, ray.d.z));
            double ix = Reciprocal(ray.d.x), iy = Reciprocal(ray.d.y), iz = Reciprocal(ray.d.z);
            _ix = Vector256.Create(ix);
            _iy = Vector256.Create(iy);
            _iz = Vector256.Create(iz);
            _nearX = ix < 0 ? 3 : 0;
            _nearY = iy < 0 ? 4 : 1;
            _nearZ = iz < 0 ? 5 : 2;
        }

        /// <summary>
        /// Bit i set when the segment [0, tMax] meets child box i; <paramref name="enter"/> holds the entry distances.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public int Hits(ref Bvh4Node node, double tMax, out Vector256<double> enter)
        {
            // (plane − o) / d is monotonic in the plane for a fixed sign of 1/d (rounding is monotonic too), so
            // the near plane's distance is the smaller of the two that a min/max pair would have picked.
            ref var planes = ref Unsafe.As<Bvh4Node, Vector128<float>>(ref node);
            Vector256<double> nx = (Widen(Unsafe.Add(ref planes, _nearX)) - _ox) * _ix, fx = (Widen(Unsafe.Add(ref planes, 3 - _nearX)) - _fx) * _ix;
            Vector256<double> ny = (Widen(Unsafe.Add(ref planes, _nearY)) - _oy) * _iy, fy = (Widen(Unsafe.Add(ref planes, 5 - _nearY)) - _fy) * _iy;
            Vector256<double> nz = (Widen(Unsafe.Add(ref planes, _nearZ)) - _oz) * _iz, fz = (Widen(Unsafe.Add(ref planes, 7 - _nearZ)) - _fz) * _iz;
            // The native forms map to single instructions; they differ from Min/Max only for NaN
            // and signed zeros, and the finite reciprocals above never produce NaN.
            var t0 = Vector256.MaxNative(Vector256.MaxNative(nx, ny), Vector256.MaxNative(nz, Vector256<double>.Zero));
            var t1 = Vector256.MinNative(Vector256.MinNative(fx, fy), Vector256.MinNative(fz, Vector256.Create(tMax)));
            enter = t0;
            return (int)Vector256.LessThanOrEqual(t0, t1 * FarSlackVector).ExtractMostSignificantBits() & node.ValidMask;
        }

        /// <summary>The four floats as doubles (exact); one instruction with AVX, whose form can read memory directly.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> Widen(Vector128<float> v) =>
            Avx.IsSupported ? Avx.ConvertToVector256Double(v) : Vector256.WidenLower(v.ToVector256Unsafe());

        /// <summary>
        /// 1/d with zero mapped to a huge finite value of the same sign: 0 · huge is 0 rather than NaN,
        /// so a ray lying in a slab plane counts as inside that slab.
        /// </summary>
        private static double Reciprocal(double d) => d != 0 ? 1.0 / d : Math.CopySign(1e300, d);

        /// <summary>
        /// The origin coordinate the far plane's distance is measured from. A ray that does not move along an
        /// axis is inside that slab for every t when its origin lies between the planes, but with the origin
        /// on the far plane itself 0 · 1e300 made the far distance 0, and the box was missed (a ray along a
        /// face of a cube, at its edge). Moved past the far plane's side by an ulp and 1e-150, the origin puts
        /// the far plane at least 1e-150 ahead, so its distance is at least 1e150; the near plane still uses
        /// the origin itself.
        /// </summary>
        private static double FarOrigin(double o, double d) =>
            d != 0 ? o : double.IsNegative(d) ? Math.BitIncrement(o) + 1e-150 : Math.BitDecrement(o) - 1e-150;
    }
}
