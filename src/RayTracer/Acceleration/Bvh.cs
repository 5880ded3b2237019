using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Bounding volume hierarchy built top-down with the binned surface area heuristic (see
/// <see cref="BvhBuilder"/>), then collapsed into eight-wide nodes where <see cref="Vector512"/> is
/// accelerated and four-wide nodes elsewhere, whose child boxes are tested together with vector
/// instructions; leaves of triangles test as many of them at once (<see cref="TriangleGroup8Solver"/>,
/// <see cref="TriangleGroupSolver"/>). Traversal uses a fixed stack on the call stack (no allocation),
/// visits entered children nearest first and skips subtrees that start beyond the best hit so far.
/// </summary>
public sealed partial class Bvh : AccelerationStructure
{
    private const int MaxDepth = 60;

    // Each wide level pushes at most three entries beyond the one it pops.
    private const int StackSize = 3 * MaxDepth + 8;

    // Slack on far slab distances and on the best distance a subtree's entry is compared with: 1 + 2⁻²⁰.
    // The box test rounds (pbrt's 1 + 2γ₃ would cover that), and so does the triangle test: the distance it
    // computes for a hit on a box face can lie a few units in the last place below the box's computed
    // entry (seen at coordinates near 1e30 and 1e-30), and a node must not be skipped for that.
    private const double FarSlack = 1.0 + 1.0 / (1 << 20);

    private readonly BvhNode[] _nodes;
    private readonly Bvh4Node[] _wide = [];
    private readonly AlignedArray<Bvh8Node> _wide8;
    private readonly BvhLeaf[] _leaves = [];
    private readonly TriangleGroup4[] _groups = [];
    private readonly AlignedArray<TriangleGroup8> _groups8;
    private int _wideCount;
    private int _leafCount;

    /// <summary>A BVH whose leaves hold up to as many primitives as a node has children (8 or 4).</summary>
    public Bvh(IReadOnlyList<GeometricObject> objects)
        : this(objects, DefaultWidth)
    {
    }

    public Bvh(IReadOnlyList<GeometricObject> objects, int maxLeafSize)
        : this(objects, maxLeafSize, BvhBuilder.Parallelism.Default)
    {
    }

    /// <summary>As the public constructor, with the sizes from which the build shares work among threads.</summary>
    internal Bvh(IReadOnlyList<GeometricObject> objects, int maxLeafSize, BvhBuilder.Parallelism parallelism)
        : this(objects, maxLeafSize, parallelism, DefaultWidth)
    {
    }

    /// <summary>
    /// As above, with the width of the traversal nodes: 4, or 8 where <see cref="Vector512"/> is accelerated.
    /// Leaves of triangles are tested in groups of as many lanes (<see cref="TriangleGroup4"/> with the
    /// four-wide nodes, <see cref="TriangleGroup8"/> with the eight-wide ones), and the SAH counts a leaf's
    /// cost per group.
    /// </summary>
    internal Bvh(IReadOnlyList<GeometricObject> objects, int maxLeafSize, BvhBuilder.Parallelism parallelism, int width)
        : base(objects)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxLeafSize, 1);
        if (width != 4 && (width != 8 || !Vector512.IsHardwareAccelerated))
            throw new ArgumentOutOfRangeException(nameof(width), width, "4, or 8 where Vector512 is accelerated");
        MaxLeafSize = maxLeafSize;
        Width = width;
        int n = Table.Count;
        if (n == 0)
        {
            _nodes = [];
            return;
        }

        _nodes = BvhBuilder.Build(Table.Bounds, maxLeafSize, width, MaxDepth, parallelism, out var order, out int binaryNodes);
        Table.ReleaseBuildData();

        // The table is put in build order while this thread collapses levels into wide
        // nodes for traversal (the collapse reads only the binary nodes). A full binary tree of m nodes has
        // (m + 1) / 2 leaves, which stay leaves, and (m - 1) / 2 interior nodes, at least two per wide
        // node but the root; the wide array may be longer than its count, and its tail is never touched.
        var permute = parallelism.Chunk < n ? Task.Run(() => Table.Permute(order)) : null;
        if (permute is null)
            Table.Permute(order);
        // Every wide node opens at least one binary interior node, so the same bound holds for either width.
        if (width == 8)
            _wide8 = new AlignedArray<Bvh8Node>(Math.Max(1, (binaryNodes - 1) / 2));
        else
            _wide = GC.AllocateUninitializedArray<Bvh4Node>(Math.Max(1, (binaryNodes - 1) / 2));
        _leaves = GC.AllocateUninitializedArray<BvhLeaf>((binaryNodes + 1) / 2);
        if (width == 8)
            Collapse8(0);
        else
            Collapse(0);
        permute?.Wait();
        int groupCount = DescribeLeaves(_leaves, width, out bool oneByOne);
        if (width == 8)
            _groups8 = FillGroups8(_leaves, groupCount, Math.Max(1, parallelism.Chunk / 256));
        else
            _groups = FillGroups(_leaves, groupCount, Math.Max(1, parallelism.Chunk / 256));
        if (oneByOne)
            Table.PackTriangles(); // some leaves test their primitives one by one
        BinaryNodeCount = binaryNodes;
        _nodes = [];
    }

    /// <summary>The width used unless a test asks for another: 8 where <see cref="Vector512"/> is accelerated.</summary>
    internal static int DefaultWidth => Vector512.IsHardwareAccelerated ? 8 : 4;

    public int MaxLeafSize { get; }

    /// <summary>Children per traversal node: 8 or 4.</summary>
    public int Width { get; }

    /// <summary>Nodes of the binary SAH tree that was built.</summary>
    public int BinaryNodeCount { get; }

    /// <summary>Nodes of the wide tree used for traversal.</summary>
    public int NodeCount => _wideCount;

    /// <summary>How many traversal nodes have exactly <paramref name="children"/> children (for tests that need full nodes).</summary>
    internal int NodesWithChildren(int children)
    {
        int n = 0;
        for (int i = 0; i < _wideCount; i++)
            n += BitOperations.PopCount((uint)(Width == 8 ? _wide8[i].ValidMask : _wide[i].ValidMask)) == children ? 1 : 0;
        return n;
    }

    private protected override bool TraverseNearest(in Ray ray, ref double t, ref int primitive)
    {
        if (_wide8.Length != 0)
        {
            return WideRay.MovesAlongEveryAxis(ray)
                ? Nearest8<SameOrigin>(ray, ref t, ref primitive)
                : Nearest8<MovedOrigin>(ray, ref t, ref primitive);
        }

        return _wide.Length != 0 && (WideRay.MovesAlongEveryAxis(ray)
            ? Nearest<SameOrigin>(ray, ref t, ref primitive)
            : Nearest<MovedOrigin>(ray, ref t, ref primitive));
    }

    private protected override bool TraverseAny(in Ray ray, double tMax)
    {
        if (_wide8.Length != 0)
            return WideRay.MovesAlongEveryAxis(ray) ? Any8<SameOrigin>(ray, tMax) : Any8<MovedOrigin>(ray, tMax);
        return _wide.Length != 0 && (WideRay.MovesAlongEveryAxis(ray) ? Any<SameOrigin>(ray, tMax) : Any<MovedOrigin>(ray, tMax));
    }

    /// <summary>Nearest hit; <typeparamref name="TOrigin"/> says whether the box test needs <see cref="WideRay.Origins"/>' moved origins (compiled apart, so rays that move along every axis pay nothing for them).</summary>
    [SkipLocalsInit]
    private bool Nearest<TOrigin>(in Ray ray, ref double t, ref int primitive)
        where TOrigin : struct, IOrigin
    {
        var r = new WideRay(ray);
        var max = TOrigin.Moved ? WideRay.MaxOf(ray) : default;
        var nodes = _wide;
        var leaves = _leaves;
        var groups = new Groups4(_groups, ray);
        var table = Table;
        Span<int> stackRef = stackalloc int[StackSize];
        Span<double> stackEnter = stackalloc double[StackSize];
        int sp = 0;
        bool hit = false;
        int current = 0;

        while (true)
        {
            ref var node = ref nodes[current];
            int mask = r.Hits<TOrigin>(ref node, t, in max, out var enter);

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
                PushByDistance(stackRef, stackEnter, ref sp, pushedFrom, child, te);
            }

            // Pop until an interior node to descend into, testing leaves on the way.
            current = PopToInterior(in groups, leaves, table, in ray, stackRef, stackEnter, ref sp, ref t, ref primitive, ref hit);
            if (current < 0)
            {
                return hit;
            }
        }
    }

    /// <summary>
    /// Pushes a child entered at <paramref name="enter"/> among those pushed since <paramref name="pushedFrom"/>,
    /// farther ones deeper, so the nearest is popped first (both widths' nearest-hit traversals).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void PushByDistance(Span<int> stackRef, Span<double> stackEnter, ref int sp, int pushedFrom, int child, double enter)
    {
        int j = sp++;
        while (j > pushedFrom && stackEnter[j - 1] < enter)
        {
            stackEnter[j] = stackEnter[j - 1];
            stackRef[j] = stackRef[j - 1];
            j--;
        }

        stackEnter[j] = enter;
        stackRef[j] = child;
    }

    [SkipLocalsInit]
    private bool Any<TOrigin>(in Ray ray, double tMax)
        where TOrigin : struct, IOrigin
    {
        var r = new WideRay(ray);
        var max = TOrigin.Moved ? WideRay.MaxOf(ray) : default;
        var nodes = _wide;
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

            ref var node = ref nodes[reference];
            int mask = r.Hits<TOrigin>(ref node, tMax, in max, out _);
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
    /// The leaves, each with its run of groups of <paramref name="groupSize"/> lanes when all its primitives are Möller–Trumbore
    /// triangles; returns the number of groups. <paramref name="oneByOne"/> tells whether some leaf tests its
    /// primitives one by one (in one query or both), which needs the table's packed triangles.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int DescribeLeaves(BvhLeaf[] leaves, int groupSize, out bool oneByOne)
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
                leaves[l].GroupCount = (count + groupSize - 1) / groupSize;
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

    /// <summary>Copies the leaves' triangles into their eight-lane groups; lanes left over are zero and never hit.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private AlignedArray<TriangleGroup8> FillGroups8(BvhLeaf[] leaves, int groupCount, int leavesPerTask)
    {
        var groups = new AlignedArray<TriangleGroup8>(groupCount);
        ChunkedLoop.For(leaves.Length, leavesPerTask, [MethodImpl(MethodImplOptions.AggressiveOptimization)] (start, end) =>
        {
            // Nine rows of eight lanes: v0, e1, e2, each x, y, z.
            Span<double> v = stackalloc double[72];
            for (int l = start; l < end; l++)
            {
                var leaf = leaves[l];
                for (int g = 0; g < leaf.GroupCount; g++)
                {
                    int first = leaf.First + 8 * g, lanes = Math.Min(8, leaf.Count - 8 * g);
                    v.Clear();
                    for (int k = 0; k < lanes; k++)
                    {
                        var p = Table.MollerTrumbore(first + k);
                        v[k] = p.V0.x;
                        v[8 + k] = p.V0.y;
                        v[16 + k] = p.V0.z;
                        v[24 + k] = p.E1.x;
                        v[32 + k] = p.E1.y;
                        v[40 + k] = p.E1.z;
                        v[48 + k] = p.E2.x;
                        v[56 + k] = p.E2.y;
                        v[64 + k] = p.E2.z;
                    }

                    groups[leaf.Group + g] = new TriangleGroup8
                    {
                        V0 = Lanes8(v[..24]),
                        E1 = Lanes8(v[24..48]),
                        E2 = Lanes8(v[48..]),
                    };
                }
            }
        });
        return groups;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector3x8 Lanes8(ReadOnlySpan<double> xyz) =>
        new() { x = Vector512.Create(xyz[..8]), y = Vector512.Create(xyz[8..16]), z = Vector512.Create(xyz[16..24]) };

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector3x4 Lanes(double x0, double x1, double x2, double x3, double y0, double y1, double y2, double y3, double z0, double z1, double z2, double z3) =>
        new() { x = Vector256.Create(x0, x1, x2, x3), y = Vector256.Create(y0, y1, y2, y3), z = Vector256.Create(z0, z1, z2, z3) };

    /// <summary>
    /// Turns the binary subtree at <paramref name="binary"/> into a four-wide node (see <see cref="OpenChildren"/>).
    /// </summary>
    [SkipLocalsInit]
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Collapse(int binary)
    {
        Span<int> slots = stackalloc int[4];
        int count = OpenChildren(binary, slots);
        int index = _wideCount++;
        Span<double> minX = stackalloc double[4], minY = stackalloc double[4], minZ = stackalloc double[4];
        Span<double> maxX = stackalloc double[4], maxY = stackalloc double[4], maxZ = stackalloc double[4];
        Span<int> refs = stackalloc int[4];
        FillSlots(slots, count, minX, minY, minZ, maxX, maxY, maxZ, refs, eight: false);
        _wide[index] = new Bvh4Node
        {
            MinX = Vector256.Create<double>(minX),
            MinY = Vector256.Create<double>(minY),
            MinZ = Vector256.Create<double>(minZ),
            MaxX = Vector256.Create<double>(maxX),
            MaxY = Vector256.Create<double>(maxY),
            MaxZ = Vector256.Create<double>(maxZ),
            Child0 = refs[0],
            Child1 = refs[1],
            Child2 = refs[2],
            Child3 = refs[3],
            ValidMask = (1 << count) - 1,
        };
        return index;
    }

    /// <summary>
    /// Turns the binary subtree at <paramref name="binary"/> into an eight-wide node (see <see cref="OpenChildren"/>).
    /// </summary>
    [SkipLocalsInit]
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Collapse8(int binary)
    {
        Span<int> slots = stackalloc int[8];
        int count = OpenChildren(binary, slots);
        int index = _wideCount++;
        Span<double> minX = stackalloc double[8], minY = stackalloc double[8], minZ = stackalloc double[8];
        Span<double> maxX = stackalloc double[8], maxY = stackalloc double[8], maxZ = stackalloc double[8];
        Span<int> refs = stackalloc int[8];
        FillSlots(slots, count, minX, minY, minZ, maxX, maxY, maxZ, refs, eight: true);
        _wide8[index] = new Bvh8Node
        {
            MinX = Vector512.Create<double>(minX),
            MinY = Vector512.Create<double>(minY),
            MinZ = Vector512.Create<double>(minZ),
            MaxX = Vector512.Create<double>(maxX),
            MaxY = Vector512.Create<double>(maxY),
            MaxZ = Vector512.Create<double>(maxZ),
            Child0 = refs[0],
            Child1 = refs[1],
            Child2 = refs[2],
            Child3 = refs[3],
            Child4 = refs[4],
            Child5 = refs[5],
            Child6 = refs[6],
            Child7 = refs[7],
            ValidMask = (1 << count) - 1,
        };
        return index;
    }

    /// <summary>
    /// The children of a wide node for binary node <paramref name="binary"/>: its two children, then the
    /// interior child of largest surface area opened in turn until every slot is used or only leaves remain
    /// (a binary leaf as root gives one slot). Returns the number of slots used.
    /// </summary>
    private int OpenChildren(int binary, Span<int> slots)
    {
        int count = 0;
        var root = _nodes[binary];
        if (root.Count > 0)
        {
            slots[count++] = binary;
            return count;
        }

        slots[count++] = root.Offset;
        slots[count++] = root.Offset + 1;
        while (count < slots.Length)
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

        return count;
    }

    /// <summary>
    /// The boxes (exact conversions of the builder's floats) and references of the slots, in order; unused
    /// slots get zero boxes and reference 0 (masked off by the node's valid mask). Interior children are
    /// collapsed depth first (eight- or four-wide), so a subtree's nodes follow its parent.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void FillSlots(Span<int> slots, int count, Span<double> minX, Span<double> minY, Span<double> minZ,
        Span<double> maxX, Span<double> maxY, Span<double> maxZ, Span<int> refs, bool eight)
    {
        for (int i = 0; i < slots.Length; i++)
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
                refs[i] = eight ? Collapse8(slots[i]) : Collapse(slots[i]);
            }
        }
    }

    /// <summary>Whether <see cref="WideRay"/>'s test uses the moved origins (a compile-time constant for each type).</summary>
    private interface IOrigin
    {
        static abstract bool Moved { get; }
    }

    private readonly struct SameOrigin : IOrigin
    {
        public static bool Moved => false;
    }

    private readonly struct MovedOrigin : IOrigin
    {
        public static bool Moved => true;
    }

    /// <summary>The maximum planes' origins of a ray that does not move along some axis (<see cref="WideRay.MaxOf"/>).</summary>
    private readonly record struct MaxOrigins(Vector256<double> X, Vector256<double> Y, Vector256<double> Z);

    /// <summary>Ray broadcast into vectors for testing four boxes at once.</summary>
    private readonly struct WideRay
    {
        // The origin the minimum planes' distances are measured from, and the reciprocal direction.
        // Six vectors: the traversal loops keep them in registers (nine, with the maximum planes'
        // origins below, the bunny's rays measured about 5 % slower, so those are a struct of their own).
        private readonly Vector256<double> _ox, _oy, _oz, _ix, _iy, _iz;

        public WideRay(in Ray ray)
        {
            _ox = Vector256.Create(Origins(ray.o.x, ray.d.x).Min);
            _oy = Vector256.Create(Origins(ray.o.y, ray.d.y).Min);
            _oz = Vector256.Create(Origins(ray.o.z, ray.d.z).Min);
            _ix = Vector256.Create(Reciprocal(ray.d.x));
            _iy = Vector256.Create(Reciprocal(ray.d.y));
            _iz = Vector256.Create(Reciprocal(ray.d.z));
        }

        /// <summary>
        /// The origin the maximum planes' distances are measured from: the ray's origin except on an axis
        /// the ray does not move along, where it may be moved (see <see cref="Origins"/>); only the
        /// traversal for such rays reads it.
        /// </summary>
        public static MaxOrigins MaxOf(in Ray ray) =>
            new(Vector256.Create(Origins(ray.o.x, ray.d.x).Max), Vector256.Create(Origins(ray.o.y, ray.d.y).Max), Vector256.Create(Origins(ray.o.z, ray.d.z).Max));

        /// <summary>
        /// Bit i set when the segment [0, tMax] meets child box i; <paramref name="enter"/> holds the entry distances.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public int Hits<TOrigin>(ref Bvh4Node node, double tMax, in MaxOrigins max, out Vector256<double> enter)
            where TOrigin : struct, IOrigin
        {
            var mx = TOrigin.Moved ? max.X : _ox;
            var my = TOrigin.Moved ? max.Y : _oy;
            var mz = TOrigin.Moved ? max.Z : _oz;
            Vector256<double> ax = (node.MinX - _ox) * _ix, bx = (node.MaxX - mx) * _ix;
            Vector256<double> ay = (node.MinY - _oy) * _iy, by = (node.MaxY - my) * _iy;
            Vector256<double> az = (node.MinZ - _oz) * _iz, bz = (node.MaxZ - mz) * _iz;
            // The native forms map to single instructions; they differ from Min/Max only for NaN
            // and signed zeros, and the finite reciprocals above never produce NaN.
            var t0 = Vector256.MaxNative(
                Vector256.MaxNative(Vector256.MinNative(ax, bx), Vector256.MinNative(ay, by)),
                Vector256.MaxNative(Vector256.MinNative(az, bz), Vector256<double>.Zero));
            var t1 = Vector256.MinNative(
                Vector256.MinNative(Vector256.MaxNative(ax, bx), Vector256.MaxNative(ay, by)),
                Vector256.MinNative(Vector256.MaxNative(az, bz), Vector256.Create(tMax)));
            enter = t0;
            return (int)Vector256.LessThanOrEqual(t0, t1 * Vector256.Create(FarSlack)).ExtractMostSignificantBits() & node.ValidMask;
        }

        /// <summary>
        /// 1/d with zero mapped to a huge finite value of the same sign: 0 · huge is 0 rather than NaN,
        /// so a ray lying in a slab plane counts as inside that slab.
        /// </summary>
        public static double Reciprocal(double d) => d != 0 ? 1.0 / d : Math.CopySign(1e300, d);

        /// <summary>Whether no direction component is zero (NaN counts as moving: it never was handled).</summary>
        public static bool MovesAlongEveryAxis(in Ray ray) => ray.d.x != 0 && ray.d.y != 0 && ray.d.z != 0;

        /// <summary>
        /// The origin coordinate the minimum and the maximum planes' distances are measured from: o for both,
        /// unless the ray does not move along the axis. Such a ray is inside the slab for every t when o lies
        /// between the planes, but with o on the plane it would leave through (the maximum for +0, the minimum
        /// for −0) 0 · 1e300 made that distance 0, and the box was missed (a ray along a cube's face, at its
        /// edge). For that plane the origin is moved back by an ulp and 1e-150, which puts the plane at least
        /// 1e-150 ahead and its distance at 1e150 or more; the other plane keeps o.
        /// </summary>
        public static (double Min, double Max) Origins(double o, double d)
        {
            if (d != 0)
                return (o, o);
            return double.IsNegative(d) ? (Math.BitIncrement(o) + 1e-150, o) : (o, Math.BitDecrement(o) - 1e-150);
        }
    }
}
