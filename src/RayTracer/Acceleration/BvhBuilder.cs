using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Bounds;
using RayTracer.Maths;

namespace RayTracer.Acceleration;

/// <summary>
/// Top-down binned SAH build of a binary tree. Each primitive's box travels with it through the
/// partitions (min and max as two single-precision vectors, rounded outward from the double box, its
/// index in the spare lane), so binning reads and partitioning moves 32 bytes per primitive; one pass bins all three axes at once, and the partition pass also
/// gathers the children's boxes and centroid boxes. Subtrees above a size threshold are built in
/// parallel, their node pairs taken from a shared counter. The loops are compiled fully optimized
/// at once (a build runs each of them only a few times, too few for tiered compilation to get there).
/// </summary>
internal sealed class BvhBuilder
{
    private const int BinCount = 16;

    /// <summary>Subtrees smaller than this are built on the calling thread.</summary>
    private const int ParallelThreshold = 8192;

    /// <summary>Ranges at least this large are binned by all processors together.</summary>
    private const int ParallelBinning = 1 << 17;

    /// <summary>Primitives per work item of the parallel loops over all of them.</summary>
    private const int ChunkSize = 1 << 16;
    private const double TraversalCost = 1.0;
    private const double IntersectionCost = 1.0;

    private readonly PrimitiveReference[] _refs;
    private readonly BvhNode[] _nodes;
    private readonly int _maxLeafSize;
    private readonly int _maxDepth;
    private int _nodeCount;

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private BvhBuilder(BoundingBox[] bounds, int maxLeafSize, int maxDepth)
    {
        int n = bounds.Length;
        // Written before read: no need to zero them (nodes past the count are never touched).
        _refs = GC.AllocateUninitializedArray<PrimitiveReference>(n);
        ChunkedLoop.For(n, ChunkSize, (start, end) =>
        {
            for (int i = start; i < end; i++)
            {
                ref readonly var b = ref bounds[i];
                _refs[i] = new PrimitiveReference(
                    Vector128.Create(Down(b.Min.x), Down(b.Min.y), Down(b.Min.z), BitConverter.Int32BitsToSingle(i)),
                    Vector128.Create(Up(b.Max.x), Up(b.Max.y), Up(b.Max.z), 0));
            }
        });

        _nodes = GC.AllocateUninitializedArray<BvhNode>(Math.Max(1, 2 * n - 1));
        _maxLeafSize = maxLeafSize;
        _maxDepth = maxDepth;
    }

    /// <summary>
    /// Builds the tree over <paramref name="bounds"/> with its root at 0; order[i] is the primitive at build
    /// position i, and the first <paramref name="nodeCount"/> nodes are used.
    /// </summary>
    public static BvhNode[] Build(BoundingBox[] bounds, int maxLeafSize, int maxDepth, out int[] order, out int nodeCount)
    {
        var builder = new BvhBuilder(bounds, maxLeafSize, maxDepth);
        int n = bounds.Length;
        var root = (Box: Empty, Centroids: Empty);
        var gate = new object();
        ChunkedLoop.For(n, ChunkSize, (start, end) =>
        {
            var part = builder.Bounds(start, end);
            lock (gate)
                root = (Union(root.Box, part.Box), Union(root.Centroids, part.Centroids));
        });

        builder._nodeCount = 1;
        builder.Subtree(0, 0, n, root.Box, root.Centroids, 0);
        var refs = builder._refs;
        var positions = GC.AllocateUninitializedArray<int>(n);
        ChunkedLoop.For(n, ChunkSize, (start, end) =>
        {
            for (int i = start; i < end; i++)
                positions[i] = refs[i].Index;
        });
        order = positions;
        nodeCount = builder._nodeCount;

        // Nodes past the count are never referred to; the array is returned as is rather than copied.
        return builder._nodes;
    }

    /// <summary>Leaf tests cost per four-lane group: up to four triangles are tested for the price of one.</summary>
    public static int GroupsOf(int count) => (count + 3) >> 2;

    private static Box Empty => new(Vector128.Create(float.PositiveInfinity), Vector128.Create(float.NegativeInfinity));

    /// <summary>The largest float not above <paramref name="x"/>.</summary>
    private static float Down(double x)
    {
        float f = (float)x;
        return f > x ? MathF.BitDecrement(f) : f;
    }

    /// <summary>The smallest float not below <paramref name="x"/>.</summary>
    private static float Up(double x)
    {
        float f = (float)x;
        return f < x ? MathF.BitIncrement(f) : f;
    }

    /// <summary>
    /// Fills node <paramref name="index"/> with the subtree over [start, end), whose box is
    /// <paramref name="box"/> and whose doubled centroids span <paramref name="centroids"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Subtree(int index, int start, int end, Box box, Box centroids, int depth)
    {
        int count = end - start;
        var extent = centroids.Max - centroids.Min;
        // Up to four primitives cost one group test, less than any split (which adds a traversal step).
        if (count <= Math.Min(_maxLeafSize, 4))
        {
            _nodes[index] = new BvhNode { Bounds = box.ToBoundingBox(), Offset = start, Count = count };
            return;
        }

        if (depth >= _maxDepth || !(Vector128.GreaterThanAny(extent.WithElement(3, 0), Vector128<float>.Zero)))
        {
            if (count > _maxLeafSize && depth < _maxDepth)
            {
                // All centroids coincide: split the range in half to keep leaves small.
                int half = start + count / 2;
                Interior(index, start, half, end, Bounds(start, half), Bounds(half, end), depth);
                return;
            }

            _nodes[index] = new BvhNode { Bounds = box.ToBoundingBox(), Offset = start, Count = count };
            return;
        }

        var (axis, split, cost) = BestSplit(start, end, centroids);
        double splitCost = TraversalCost + IntersectionCost * cost / Math.Max(box.SurfaceArea, double.Epsilon);
        if (axis < 0 || (splitCost >= IntersectionCost * GroupsOf(count) && count <= _maxLeafSize))
        {
            if (axis >= 0 || count <= _maxLeafSize)
            {
                _nodes[index] = new BvhNode { Bounds = box.ToBoundingBox(), Offset = start, Count = count };
                return;
            }

            int half = start + count / 2;
            Interior(index, start, half, end, Bounds(start, half), Bounds(half, end), depth);
            return;
        }

        int mid = Partition(start, end, axis, BinScale(centroids, BinsFor(count)), split, out var left, out var right);
        Interior(index, start, mid, end, left, right, depth);
    }

    private void Interior(int index, int start, int mid, int end, (Box Box, Box Centroids) left, (Box Box, Box Centroids) right, int depth)
    {
        int first = Interlocked.Add(ref _nodeCount, 2) - 2;
        _nodes[index] = new BvhNode { Bounds = Union(left.Box, right.Box).ToBoundingBox(), Offset = first, Count = 0 };
        if (end - start >= ParallelThreshold)
        {
            var task = Task.Run(() => Subtree(first, start, mid, left.Box, left.Centroids, depth + 1));
            Subtree(first + 1, mid, end, right.Box, right.Centroids, depth + 1);
            task.Wait();
        }
        else
        {
            Subtree(first, start, mid, left.Box, left.Centroids, depth + 1);
            Subtree(first + 1, mid, end, right.Box, right.Centroids, depth + 1);
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private (Box Box, Box Centroids) Bounds(int start, int end)
    {
        var box = Empty;
        var centroids = Empty;
        var refs = _refs;
        for (int i = start; i < end; i++)
        {
            box.Include(refs[i].Min, refs[i].Max);
            centroids.Include(refs[i].Centroid);
        }

        return (box, centroids);
    }

    /// <summary>
    /// Bins the doubled centroids on every axis with a spread in one pass and returns the cheapest
    /// plane: its axis (−1 when no plane leaves both sides non-empty), bin boundary and SAH cost
    /// (area-weighted group counts).
    /// </summary>
    [SkipLocalsInit]
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private (int Axis, int Split, double Cost) BestSplit(int start, int end, Box centroids)
    {
        Span<Box> bins = stackalloc Box[3 * BinCount];
        Span<int> counts = stackalloc int[3 * BinCount];
        int count = end - start;
        int binCount = BinsFor(count);
        var (lo, scale, _) = BinScale(centroids, binCount);
        var extent = centroids.Max - lo;
        if (count < ParallelBinning)
        {
            Bin(start, end, lo, scale, binCount, bins, counts);
        }
        else
        {
            // Near the root the subtrees are still few: the processors bin slices and the bins are merged.
            int slices = Environment.ProcessorCount;
            var sliceBins = new Box[slices][];
            var sliceCounts = new int[slices][];
            Parallel.For(0, slices, k =>
            {
                sliceBins[k] = new Box[3 * BinCount];
                sliceCounts[k] = new int[3 * BinCount];
                Bin(start + (int)((long)count * k / slices), start + (int)((long)count * (k + 1) / slices), lo, scale, binCount, sliceBins[k], sliceCounts[k]);
            });
            bins.Fill(Empty);
            counts.Clear();
            for (int k = 0; k < slices; k++)
            {
                for (int b = 0; b < bins.Length; b++)
                {
                    bins[b] = Union(bins[b], sliceBins[k][b]);
                    counts[b] += sliceCounts[k][b];
                }
            }
        }

        int bestAxis = -1, bestSplit = 1;
        double bestCost = double.PositiveInfinity;
        Span<double> rightArea = stackalloc double[BinCount];
        Span<int> rightCount = stackalloc int[BinCount];
        for (int axis = 0; axis < 3; axis++)
        {
            if (!(extent.GetElement(axis) > 0))
                continue;
            var axisBins = bins.Slice(axis * BinCount, binCount);
            var axisCounts = counts.Slice(axis * BinCount, binCount);

            // Sweep from the right for the area and count of every right-hand side, then from the left.
            var acc = Empty;
            int accCount = 0;
            for (int b = binCount - 1; b > 0; b--)
            {
                acc = Union(acc, axisBins[b]);
                accCount += axisCounts[b];
                rightArea[b] = acc.SurfaceArea;
                rightCount[b] = accCount;
            }

            acc = Empty;
            accCount = 0;
            for (int b = 1; b < binCount; b++)
            {
                acc = Union(acc, axisBins[b - 1]);
                accCount += axisCounts[b - 1];
                if (accCount == 0 || rightCount[b] == 0)
                    continue;
                double cost = acc.SurfaceArea * GroupsOf(accCount) + rightArea[b] * GroupsOf(rightCount[b]);
                if (cost < bestCost)
                {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = b;
                }
            }
        }

        return (bestAxis, bestSplit, bestCost);
    }

    /// <summary>Counts and bounds the primitives of [start, end) in the bins of their doubled centroids on each axis.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Bin(int start, int end, Vector128<float> lo, Vector128<float> scale, int binCount, Span<Box> bins, Span<int> counts)
    {
        for (int axis = 0; axis < 3; axis++)
        {
            bins.Slice(axis * BinCount, binCount).Fill(Empty);
            counts.Slice(axis * BinCount, binCount).Clear();
        }

        var last = Vector128.Create(binCount - 1);
        var refs = _refs;
        for (int i = start; i < end; i++)
        {
            var min = refs[i].Min;
            var max = refs[i].Max;
            var b = BinsOf(refs[i].Centroid, lo, scale, last);
            int bx = b.GetElement(0), by = BinCount + b.GetElement(1), bz = 2 * BinCount + b.GetElement(2);
            bins[bx].Include(min, max);
            counts[bx]++;
            bins[by].Include(min, max);
            counts[by]++;
            bins[bz].Include(min, max);
            counts[bz]++;
        }
    }

    /// <summary>
    /// Moves the primitives whose centroid bins below <paramref name="split"/> to the front and returns
    /// the boundary, with the boxes and centroid boxes of both sides.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Partition(int start, int end, int axis, (Vector128<float> Lo, Vector128<float> Scale, Vector128<int> Last) bins, int split,
        out (Box Box, Box Centroids) left, out (Box Box, Box Centroids) right)
    {
        var refs = _refs;
        Box lb = Empty, lc = Empty, rb = Empty, rc = Empty;
        int l = start, r = end - 1;
        while (l <= r)
        {
            var p = refs[l];
            var c = p.Centroid;
            if (BinsOf(c, bins.Lo, bins.Scale, bins.Last).GetElement(axis) < split)
            {
                lb.Include(p.Min, p.Max);
                lc.Include(c);
                l++;
            }
            else
            {
                rb.Include(p.Min, p.Max);
                rc.Include(c);
                refs[l] = refs[r];
                refs[r] = p;
                r--;
            }
        }

        left = (lb, lc);
        right = (rb, rc);
        return l;
    }

    /// <summary>Origin and scale that map doubled centroids to bins; the same for binning and partitioning.</summary>
    private static (Vector128<float> Lo, Vector128<float> Scale, Vector128<int> Last) BinScale(Box centroids, int binCount) =>
        (centroids.Min, Vector128.Create(binCount * (1 - 1e-6f)) / Vector128.MaxNative(centroids.Max - centroids.Min, Vector128.Create(float.Epsilon)),
         Vector128.Create(binCount - 1));

    /// <summary>Bins for a range: small ranges get fewer, which costs them less to sweep.</summary>
    private static int BinsFor(int count) => Math.Min(BinCount, count);

    /// <summary>The bin of a doubled centroid on each axis (lane 3 is meaningless).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector128<int> BinsOf(Vector128<float> c, Vector128<float> lo, Vector128<float> scale, Vector128<int> last) =>
        Vector128.Min(Vector128.Max(Vector128.ConvertToInt32((c - lo) * scale), Vector128<int>.Zero), last);

    private static Box Union(Box a, Box b) => new(Vector128.MinNative(a.Min, b.Min), Vector128.MaxNative(a.Max, b.Max));

    /// <summary>
    /// A primitive's box rounded outward to single precision, with its index in the fourth lane of
    /// <see cref="Min"/> (as bits; the lane is never read as a coordinate), so the partitions move 32 bytes.
    /// </summary>
    private readonly struct PrimitiveReference(Vector128<float> min, Vector128<float> max)
    {
        public readonly Vector128<float> Min = min;
        public readonly Vector128<float> Max = max;

        public int Index => BitConverter.SingleToInt32Bits(Min.GetElement(3));

        /// <summary>Twice the centre, fourth lane zero: the index bits read as a float are subnormal, and arithmetic on them is slow.</summary>
        public Vector128<float> Centroid
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => (Min + Max) & Vector128.Create(-1, -1, -1, 0).AsSingle();
        }
    }

    /// <summary>A box as two vectors (x, y, z and an unused fourth lane).</summary>
    private struct Box(Vector128<float> min, Vector128<float> max)
    {
        public Vector128<float> Min = min;
        public Vector128<float> Max = max;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Include(Vector128<float> min, Vector128<float> max)
        {
            // The native forms are single instructions; they differ only for NaN and signed zeros.
            Min = Vector128.MinNative(Min, min);
            Max = Vector128.MaxNative(Max, max);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Include(Vector128<float> p) => Include(p, p);

        public readonly double SurfaceArea
        {
            get
            {
                // xy + yz + zx as d · (y, z, x), lane 3 zeroed.
                var d = (Max - Min).WithElement(3, 0);
                var p = d * Vector128.Shuffle(d, Vector128.Create(1, 2, 0, 3));
                return d.GetElement(0) < 0 ? 0 : 2.0 * Vector128.Sum(p);
            }
        }

        public readonly BoundingBox ToBoundingBox() => new(
            new Point3D(Min.GetElement(0), Min.GetElement(1), Min.GetElement(2)),
            new Point3D(Max.GetElement(0), Max.GetElement(1), Max.GetElement(2)));
    }
}
