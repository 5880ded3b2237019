using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Bounds;
using RayTracer.Maths;

namespace RayTracer.Acceleration;

/// <summary>
/// Top-down binned SAH build of a binary tree. Each primitive's box travels with it through the
/// partitions (min and max in two vectors, the primitive's index in the fourth lane of the min), so
/// binning reads memory in order; one pass bins all three axes at once, and the partition pass also
/// gathers the children's boxes and centroid boxes. Subtrees above a size threshold are built in
/// parallel, their node pairs taken from a shared counter.
/// </summary>
internal sealed class BvhBuilder
{
    private const int BinCount = 16;

    /// <summary>Subtrees smaller than this are built on the calling thread.</summary>
    private const int ParallelThreshold = 8192;
    private const double TraversalCost = 1.0;
    private const double IntersectionCost = 1.0;

    private readonly Vector256<double>[] _min;
    private readonly Vector256<double>[] _max;
    private readonly BvhNode[] _nodes;
    private readonly int _maxLeafSize;
    private readonly int _maxDepth;
    private int _nodeCount;

    private BvhBuilder(BoundingBox[] bounds, int maxLeafSize, int maxDepth)
    {
        int n = bounds.Length;
        _min = new Vector256<double>[n];
        _max = new Vector256<double>[n];
        for (int i = 0; i < n; i++)
        {
            ref readonly var b = ref bounds[i];
            _min[i] = Vector256.Create(b.Min.x, b.Min.y, b.Min.z, i);
            _max[i] = Vector256.Create(b.Max.x, b.Max.y, b.Max.z, 0);
        }

        _nodes = new BvhNode[Math.Max(1, 2 * n - 1)];
        _maxLeafSize = maxLeafSize;
        _maxDepth = maxDepth;
    }

    /// <summary>Builds the tree over <paramref name="bounds"/>; order[i] is the primitive at build position i.</summary>
    public static BvhNode[] Build(BoundingBox[] bounds, int maxLeafSize, int maxDepth, out int[] order)
    {
        var builder = new BvhBuilder(bounds, maxLeafSize, maxDepth);
        int n = bounds.Length;
        var box = Empty;
        var centroids = Empty;
        for (int i = 0; i < n; i++)
        {
            box.Include(builder._min[i], builder._max[i]);
            centroids.Include(builder._min[i] + builder._max[i]);
        }

        builder._nodeCount = 1;
        builder.Subtree(0, 0, n, box, centroids, 0);
        order = new int[n];
        for (int i = 0; i < n; i++)
            order[i] = (int)builder._min[i].GetElement(3);
        return builder._nodes[..builder._nodeCount];
    }

    /// <summary>Leaf tests cost per four-lane group: up to four triangles are tested for the price of one.</summary>
    public static int GroupsOf(int count) => (count + 3) >> 2;

    private static Box Empty => new(Vector256.Create(double.PositiveInfinity), Vector256.Create(double.NegativeInfinity));

    /// <summary>
    /// Fills node <paramref name="index"/> with the subtree over [start, end), whose box is
    /// <paramref name="box"/> and whose doubled centroids span <paramref name="centroids"/>.
    /// </summary>
    private void Subtree(int index, int start, int end, Box box, Box centroids, int depth)
    {
        int count = end - start;
        var extent = centroids.Max - centroids.Min;
        if (count == 1 || depth >= _maxDepth || !(Vector256.GreaterThanAny(extent.WithElement(3, 0), Vector256<double>.Zero)))
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

        double lo = centroids.Min.GetElement(axis), scale = BinCount * (1 - 1e-9) / Math.Max(extent.GetElement(axis), double.Epsilon);
        int mid = Partition(start, end, axis, lo, scale, split, out var left, out var right);
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

    private (Box Box, Box Centroids) Bounds(int start, int end)
    {
        var box = Empty;
        var centroids = Empty;
        for (int i = start; i < end; i++)
        {
            box.Include(_min[i], _max[i]);
            centroids.Include(_min[i] + _max[i]);
        }

        return (box, centroids);
    }

    /// <summary>
    /// Bins the doubled centroids on every axis with a spread in one pass and returns the cheapest
    /// plane: its axis (−1 when no plane leaves both sides non-empty), bin boundary and SAH cost
    /// (area-weighted group counts).
    /// </summary>
    [SkipLocalsInit]
    private (int Axis, int Split, double Cost) BestSplit(int start, int end, Box centroids)
    {
        Span<Box> bins = stackalloc Box[3 * BinCount];
        Span<int> counts = stackalloc int[3 * BinCount];
        bins.Fill(Empty);
        counts.Clear();
        var lo = centroids.Min;
        var extent = centroids.Max - lo;
        var scale = Vector256.Create(BinCount * (1 - 1e-9)) / Vector256.Max(extent, Vector256.Create(double.Epsilon));
        var last = Vector256.Create(BinCount - 1.0);
        for (int i = start; i < end; i++)
        {
            var min = _min[i];
            var max = _max[i];
            var b = Vector256.Min(Vector256.Max(Vector256.Floor((min + max - lo) * scale), Vector256<double>.Zero), last);
            int bx = (int)b.GetElement(0), by = BinCount + (int)b.GetElement(1), bz = 2 * BinCount + (int)b.GetElement(2);
            bins[bx].Include(min, max);
            counts[bx]++;
            bins[by].Include(min, max);
            counts[by]++;
            bins[bz].Include(min, max);
            counts[bz]++;
        }

        int bestAxis = -1, bestSplit = 1;
        double bestCost = double.PositiveInfinity;
        Span<double> rightArea = stackalloc double[BinCount];
        Span<int> rightCount = stackalloc int[BinCount];
        for (int axis = 0; axis < 3; axis++)
        {
            if (!(extent.GetElement(axis) > 0))
                continue;
            var axisBins = bins.Slice(axis * BinCount, BinCount);
            var axisCounts = counts.Slice(axis * BinCount, BinCount);

            // Sweep from the right for the area and count of every right-hand side, then from the left.
            var acc = Empty;
            int accCount = 0;
            for (int b = BinCount - 1; b > 0; b--)
            {
                acc = Union(acc, axisBins[b]);
                accCount += axisCounts[b];
                rightArea[b] = acc.SurfaceArea;
                rightCount[b] = accCount;
            }

            acc = Empty;
            accCount = 0;
            for (int b = 1; b < BinCount; b++)
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

    /// <summary>
    /// Moves the primitives whose centroid bins below <paramref name="split"/> to the front and returns
    /// the boundary, with the boxes and centroid boxes of both sides.
    /// </summary>
    private int Partition(int start, int end, int axis, double lo, double scale, int split,
        out (Box Box, Box Centroids) left, out (Box Box, Box Centroids) right)
    {
        var min = _min;
        var max = _max;
        Box lb = Empty, lc = Empty, rb = Empty, rc = Empty;
        int l = start, r = end - 1;
        while (l <= r)
        {
            var c = min[l] + max[l];
            if (BinOf(c.GetElement(axis), lo, scale) < split)
            {
                lb.Include(min[l], max[l]);
                lc.Include(c);
                l++;
            }
            else
            {
                rb.Include(min[l], max[l]);
                rc.Include(c);
                (min[l], min[r]) = (min[r], min[l]);
                (max[l], max[r]) = (max[r], max[l]);
                r--;
            }
        }

        left = (lb, lc);
        right = (rb, rc);
        return l;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int BinOf(double c, double lo, double scale) =>
        Math.Clamp((int)Math.Floor((c - lo) * scale), 0, BinCount - 1);

    private static Box Union(Box a, Box b) => new(Vector256.Min(a.Min, b.Min), Vector256.Max(a.Max, b.Max));

    /// <summary>A box as two vectors (x, y, z and an unused fourth lane).</summary>
    private struct Box(Vector256<double> min, Vector256<double> max)
    {
        public Vector256<double> Min = min;
        public Vector256<double> Max = max;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Include(Vector256<double> min, Vector256<double> max)
        {
            Min = Vector256.Min(Min, min);
            Max = Vector256.Max(Max, max);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Include(Vector256<double> p) => Include(p, p);

        public readonly double SurfaceArea
        {
            get
            {
                var d = Max - Min;
                double x = d.GetElement(0), y = d.GetElement(1), z = d.GetElement(2);
                return x < 0 ? 0 : 2 * (x * y + y * z + z * x);
            }
        }

        public readonly BoundingBox ToBoundingBox() => new(
            new Point3D(Min.GetElement(0), Min.GetElement(1), Min.GetElement(2)),
            new Point3D(Max.GetElement(0), Max.GetElement(1), Max.GetElement(2)));
    }
}
