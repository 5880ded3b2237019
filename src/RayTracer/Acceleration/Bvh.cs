using System.Runtime.CompilerServices;
using RayTracer.Geometry;
using RayTracer.Util;

namespace RayTracer.Acceleration;

/// <summary>
/// Bounding volume hierarchy built with the binned surface area heuristic, stored as a flat array of
/// nodes in depth-first order and traversed with a fixed stack on the call stack (no allocation).
/// Children are visited near-first according to the sign of the ray direction on the split axis.
/// </summary>
public sealed class Bvh : AccelerationStructure
{
    private const int BinCount = 16;
    private const int MaxDepth = 60;
    private const double TraversalCost = 1.0;
    private const double IntersectionCost = 1.0;

    // Rounding slack on far slab distances (pbrt's 1 + 2γ₃) so no ray slips between adjacent boxes.
    private const double FarSlack = 1.0 + 6.0 * 1.1102230246251565e-16;

    private readonly BvhNode[] _nodes;

    public Bvh(IReadOnlyList<GeometricObject> objects, int maxLeafSize = 4)
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

        var order = new int[n];
        for (int i = 0; i < n; i++)
        {
            order[i] = i;
        }

        var nodes = new List<BvhNode>(2 * n / Math.Max(1, maxLeafSize) + 1);
        Build(nodes, order, 0, n, 0);
        _nodes = [.. nodes];
        Table.Permute(order);
        Table.ReleaseBuildData();
    }

    public int MaxLeafSize { get; }

    public int NodeCount => _nodes.Length;

    private protected override bool TraverseNearest(in Ray ray, ref double t, ref int primitive)
    {
        var r = new SlabRay(ray);
        BvhNode[] nodes = _nodes;
        PrimitiveTable table = Table;
        if (!r.Hits(ref nodes[0], t, out _))
        {
            return false;
        }

        Span<int> stackNode = stackalloc int[MaxDepth + 4];
        Span<double> stackEnter = stackalloc double[MaxDepth + 4];
        int sp = 0, current = 0;
        bool hit = false;

        while (true)
        {
            ref BvhNode node = ref nodes[current];
            if (node.Count == 0)
            {
                // Test both children here so that only boxes the ray enters are visited, nearest first.
                int a = current + 1, b = node.Offset;
                bool hitA = r.Hits(ref nodes[a], t, out double ta);
                bool hitB = r.Hits(ref nodes[b], t, out double tb);
                if (hitA && hitB)
                {
                    if (tb < ta)
                    {
                        (a, b) = (b, a);
                        tb = ta;
                    }

                    stackNode[sp] = b;
                    stackEnter[sp++] = tb;
                    current = a;
                    continue;
                }

                if (hitA)
                {
                    current = a;
                    continue;
                }

                if (hitB)
                {
                    current = b;
                    continue;
                }
            }
            else
            {
                int end = node.Offset + node.Count;
                for (int i = node.Offset; i < end; i++)
                {
                    if (table.Intersect(i, ray, t, out double ti))
                    {
                        t = ti;
                        primitive = i;
                        hit = true;
                    }
                }
            }

            // Pop the next subtree that may still hold something closer than the best hit so far.
            do
            {
                if (sp == 0)
                {
                    return hit;
                }

                current = stackNode[--sp];
            }
            while (stackEnter[sp] > t);
        }
    }

    private protected override bool TraverseAny(in Ray ray, double tMax)
    {
        var r = new SlabRay(ray);
        Span<int> stack = stackalloc int[MaxDepth + 4];
        int sp = 0, current = 0;
        BvhNode[] nodes = _nodes;
        PrimitiveTable table = Table;

        while (true)
        {
            ref BvhNode node = ref nodes[current];
            if (r.Hits(ref node, tMax, out _))
            {
                if (node.Count > 0)
                {
                    int end = node.Offset + node.Count;
                    for (int i = node.Offset; i < end; i++)
                    {
                        if (table.Occludes(i, ray, tMax))
                        {
                            return true;
                        }
                    }
                }
                else
                {
                    stack[sp++] = node.Offset;
                    current++;
                    continue;
                }
            }

            if (sp == 0)
            {
                return false;
            }

            current = stack[--sp];
        }
    }

    /// <summary>Builds the subtree over order[start..end) and returns its node index.</summary>
    private int Build(List<BvhNode> nodes, int[] order, int start, int end, int depth)
    {
        BoundingBox[] bounds = Table.Bounds;
        Point3D[] centroids = Table.Centroids;
        BoundingBox box = BoundingBox.Empty, centroidBox = BoundingBox.Empty;
        for (int i = start; i < end; i++)
        {
            box.Include(bounds[order[i]]);
            centroidBox.Include(centroids[order[i]]);
        }

        int index = nodes.Count;
        nodes.Add(new BvhNode { Bounds = box });
        int count = end - start;
        int axis = centroidBox.LongestAxis;
        double lo = centroidBox.Min[axis], hi = centroidBox.Max[axis];

        if (count <= 1 || depth >= MaxDepth || !(hi > lo))
        {
            if (count > MaxLeafSize && depth < MaxDepth && count > 1)
            {
                // All centroids coincide: split the range in half to keep leaves small.
                int half = start + count / 2;
                return MakeInterior(nodes, order, index, start, half, end, depth, axis, box);
            }

            return MakeLeaf(nodes, index, start, count, box);
        }

        int mid = FindSahSplit(order, start, end, axis, lo, hi, box, out bool makeLeaf);
        if (makeLeaf && count <= MaxLeafSize)
        {
            return MakeLeaf(nodes, index, start, count, box);
        }

        return MakeInterior(nodes, order, index, start, mid, end, depth, axis, box);
    }

    private int MakeInterior(List<BvhNode> nodes, int[] order, int index, int start, int mid, int end, int depth, int axis, BoundingBox box)
    {
        Build(nodes, order, start, mid, depth + 1);
        int second = Build(nodes, order, mid, end, depth + 1);
        nodes[index] = new BvhNode { Bounds = box, Offset = second, Count = 0, Axis = axis };
        return index;
    }

    private static int MakeLeaf(List<BvhNode> nodes, int index, int start, int count, BoundingBox box)
    {
        nodes[index] = new BvhNode { Bounds = box, Offset = start, Count = count };
        return index;
    }

    /// <summary>Bins centroids along the axis, picks the cheapest SAH plane and partitions order[start..end) around it.</summary>
    private int FindSahSplit(int[] order, int start, int end, int axis, double lo, double hi, BoundingBox box, out bool makeLeaf)
    {
        BoundingBox[] bounds = Table.Bounds;
        Point3D[] centroids = Table.Centroids;
        Span<int> binCounts = stackalloc int[BinCount];
        var binBounds = new BoundingBox[BinCount];
        for (int b = 0; b < BinCount; b++)
        {
            binBounds[b] = BoundingBox.Empty;
        }

        double scale = BinCount * (1 - 1e-9) / (hi - lo);
        for (int i = start; i < end; i++)
        {
            int b = BinOf(centroids[order[i]][axis], lo, scale);
            binCounts[b]++;
            binBounds[b].Include(bounds[order[i]]);
        }

        // Sweep from the right to get the area and count of every right-hand side.
        Span<double> rightArea = stackalloc double[BinCount];
        Span<int> rightCount = stackalloc int[BinCount];
        BoundingBox acc = BoundingBox.Empty;
        int accCount = 0;
        for (int b = BinCount - 1; b > 0; b--)
        {
            acc.Include(binBounds[b]);
            accCount += binCounts[b];
            rightArea[b] = acc.SurfaceArea;
            rightCount[b] = accCount;
        }

        double bestCost = double.PositiveInfinity;
        int bestSplit = 1;
        acc = BoundingBox.Empty;
        accCount = 0;
        for (int b = 1; b < BinCount; b++)
        {
            acc.Include(binBounds[b - 1]);
            accCount += binCounts[b - 1];
            if (accCount == 0 || rightCount[b] == 0)
            {
                continue;
            }

            double cost = acc.SurfaceArea * accCount + rightArea[b] * rightCount[b];
            if (cost < bestCost)
            {
                bestCost = cost;
                bestSplit = b;
            }
        }

        int count = end - start;
        double parentArea = box.SurfaceArea;
        double splitCost = TraversalCost + IntersectionCost * bestCost / Math.Max(parentArea, double.Epsilon);
        makeLeaf = splitCost >= IntersectionCost * count;

        // Partition: bins below bestSplit go left.
        int left = start, right = end - 1;
        while (left <= right)
        {
            if (BinOf(centroids[order[left]][axis], lo, scale) < bestSplit)
            {
                left++;
            }
            else
            {
                (order[left], order[right]) = (order[right], order[left]);
                right--;
            }
        }

        if (left == start || left == end)
        {
            left = start + count / 2; // cannot happen with non-empty sides, kept as a guard
        }

        return left;
    }

    /// <summary>Ray prepared for slab tests: reciprocal direction and, per axis, which box side is entered first.</summary>
    private readonly struct SlabRay
    {
        private readonly double _ox, _oy, _oz, _ix, _iy, _iz;
        private readonly bool _negX, _negY, _negZ;

        public SlabRay(in Ray ray)
        {
            _ox = ray.o.x;
            _oy = ray.o.y;
            _oz = ray.o.z;
            _ix = 1.0 / ray.d.x;
            _iy = 1.0 / ray.d.y;
            _iz = 1.0 / ray.d.z;
            _negX = _ix < 0;
            _negY = _iy < 0;
            _negZ = _iz < 0;
        }

        /// <summary>
        /// Whether the ray's segment [0, tMax] meets the node's box. The near/far sides are chosen from
        /// the direction signs, so no swaps are needed; a NaN from 0 · ∞ fails the comparisons and
        /// leaves the interval unchanged (a ray lying in a slab plane stays inside that slab).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Hits(ref BvhNode node, double tMax, out double tEnter)
        {
            ref BoundingBox b = ref node.Bounds;
            double t0 = 0, t1 = tMax;
            double near = ((_negX ? b.Max.x : b.Min.x) - _ox) * _ix;
            double far = ((_negX ? b.Min.x : b.Max.x) - _ox) * _ix * FarSlack;
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
            near = ((_negY ? b.Max.y : b.Min.y) - _oy) * _iy;
            far = ((_negY ? b.Min.y : b.Max.y) - _oy) * _iy * FarSlack;
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
            near = ((_negZ ? b.Max.z : b.Min.z) - _oz) * _iz;
            far = ((_negZ ? b.Min.z : b.Max.z) - _oz) * _iz * FarSlack;
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
            tEnter = t0;
            return t0 <= t1;
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int BinOf(double c, double lo, double scale) =>
        Math.Clamp((int)((c - lo) * scale), 0, BinCount - 1);
}
