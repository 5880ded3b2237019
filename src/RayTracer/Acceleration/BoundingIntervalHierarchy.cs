using System.Runtime.CompilerServices;
using RayTracer.Bounds;
using RayTracer.Geometry;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// Bounding interval hierarchy (Wächter and Keller 2006). Each node splits its candidate box at the
/// spatial middle of the longest axis, sorts objects to a side by the centre of their bounds and
/// stores only two planes: where the left objects end and where the right objects begin. When all
/// objects fall on one side, the candidate box is halved and the split retried, as in the paper.
/// Construction is a quicksort-like in-place partition, and nodes are 28 bytes.
/// </summary>
public sealed class BoundingIntervalHierarchy : AccelerationStructure
{
    private const int MaxDepth = 64;

    private readonly BihNode[] _nodes = [];
    private readonly BoundingBox _box;

    public BoundingIntervalHierarchy(IReadOnlyList<GeometricObject> objects, int maxLeafSize = 4)
        : base(objects)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxLeafSize, 1);
        MaxLeafSize = maxLeafSize;
        int n = Table.Count;
        if (n == 0)
        {
            return;
        }

        _box = Table.SceneBounds;
        var order = new int[n];
        for (int i = 0; i < n; i++)
        {
            order[i] = i;
        }

        var nodes = new List<BihNode>(n) { default };
        Build(nodes, 0, order, 0, n, _box, 0);
        _nodes = [.. nodes];
        Table.Permute(order);
        Table.ReleaseBuildData();
        Table.PackTriangles();
    }

    public int MaxLeafSize { get; }

    public int NodeCount => _nodes.Length;

    private protected override bool TraverseNearest(in Ray ray, ref double t, ref int primitive)
    {
        bool hit = false;
        int best = primitive;
        double tBest = t;
        Traverse(ray, ref tBest, ref best, ref hit, anyHit: false);
        if (hit)
        {
            t = tBest;
            primitive = best;
        }

        return hit;
    }

    private protected override bool TraverseAny(in Ray ray, double tMax)
    {
        bool hit = false;
        int best = -1;
        double t = tMax;
        Traverse(ray, ref t, ref best, ref hit, anyHit: true);
        return hit;
    }

    [SkipLocalsInit]
    private void Traverse(in Ray ray, ref double tBest, ref int best, ref bool hit, bool anyHit)
    {
        var inv = new Vector3D(1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z);
        if (!_box.Intersect(ray.o, inv, 0, tBest, out double tMin, out double tMax))
        {
            return;
        }

        // Built once per ray for triangles tested on stored Plücker edge lines.
        var rayLine = PluckerTriangleSolver.RayLine(ray);
        Span<int> stackNode = stackalloc int[MaxDepth + 4];
        Span<double> stackMin = stackalloc double[MaxDepth + 4];
        Span<double> stackMax = stackalloc double[MaxDepth + 4];
        int sp = 0, current = 0;
        var nodes = _nodes;
        var table = Table;

        while (true)
        {
            ref var node = ref nodes[current];
            if (node.Axis != BihNode.LeafAxis)
            {
                int axis = node.Axis;
                double o = ray.o[axis], d = ray.d[axis], iv = inv[axis];
                // Distances to the two planes; the near child is the one the ray reaches first.
                double tLeft = (node.LeftMax - o) * iv;
                double tRight = (node.RightMin - o) * iv;
                int nearChild, farChild;
                double nearLimit, farStart;
                if (d > 0 || (d == 0 && !double.IsNegative(d)))
                {
                    nearChild = node.Child;
                    farChild = node.Child + 1;
                    nearLimit = tLeft;
                    farStart = tRight;
                }
                else
                {
                    nearChild = node.Child + 1;
                    farChild = node.Child;
                    nearLimit = tRight;
                    farStart = tLeft;
                }

                // Written so that a NaN (ray in a clip plane) keeps the child: visiting is always safe.
                double nearMax = nearLimit < tMax ? nearLimit : tMax;
                double farMin = farStart > tMin ? farStart : tMin;
                bool visitNear = !(nearMax < tMin);
                bool visitFar = !(farMin > tMax);
                if (visitNear && visitFar)
                {
                    stackNode[sp] = farChild;
                    stackMin[sp] = farMin;
                    stackMax[sp++] = tMax;
                    current = nearChild;
                    tMax = nearMax;
                    continue;
                }

                if (visitNear)
                {
                    current = nearChild;
                    tMax = nearMax;
                    continue;
                }

                if (visitFar)
                {
                    current = farChild;
                    tMin = farMin;
                    continue;
                }
            }
            else
            {
                int end = node.Child + node.Count;
                for (int i = node.Child; i < end; i++)
                {
                    if (anyHit)
                    {
                        if (table.Occludes(i, ray, rayLine, tBest))
                        {
                            hit = true;
                            return;
                        }
                    }
                    else
                    {
                        double ti = table.Distance(i, ray, rayLine, tBest);
                        if (ti < tBest)
                        {
                            tBest = ti;
                            best = i;
                            hit = true;
                        }
                    }
                }
            }

            do
            {
                if (sp == 0)
                {
                    return;
                }

                sp--;
                current = stackNode[sp];
                tMin = stackMin[sp];
                tMax = Math.Min(stackMax[sp], tBest);
            }
            while (tMin > tBest);
        }
    }

    /// <summary>Fills node <paramref name="index"/> for order[start..end) inside the candidate box.</summary>
    private void Build(List<BihNode> nodes, int index, int[] order, int start, int end, BoundingBox candidate, int depth)
    {
        int count = end - start;
        var bounds = Table.Bounds;
        var centroids = Table.Centroids;

        // Halving the candidate box can be retried a bounded number of times before giving up.
        for (int attempt = 0; count > MaxLeafSize && depth < MaxDepth && attempt < 64; attempt++)
        {
            int axis = candidate.LongestAxis;
            double split = 0.5 * (candidate.Min[axis] + candidate.Max[axis]);
            int left = start, right = end - 1;
            double leftMax = double.NegativeInfinity, rightMin = double.PositiveInfinity;
            while (left <= right)
            {
                int o = order[left];
                if (centroids[o][axis] < split)
                {
                    leftMax = Math.Max(leftMax, bounds[o].Max[axis]);
                    left++;
                }
                else
                {
                    rightMin = Math.Min(rightMin, bounds[o].Min[axis]);
                    (order[left], order[right]) = (order[right], order[left]);
                    right--;
                }
            }

            if (left == start || left == end)
            {
                // Everything on one side: shrink the candidate box to that half and try again.
                if (left == start)
                {
                    candidate.Min = With(candidate.Min, axis, split);
                }
                else
                {
                    candidate.Max = With(candidate.Max, axis, split);
                }

                continue;
            }

            int child = nodes.Count;
            nodes.Add(default);
            nodes.Add(default);
            nodes[index] = new BihNode { Axis = axis, LeftMax = leftMax, RightMin = rightMin, Child = child };
            BoundingBox leftBox = candidate, rightBox = candidate;
            leftBox.Max = With(leftBox.Max, axis, split);
            rightBox.Min = With(rightBox.Min, axis, split);
            Build(nodes, child, order, start, left, leftBox, depth + 1);
            Build(nodes, child + 1, order, left, end, rightBox, depth + 1);
            return;
        }

        nodes[index] = new BihNode { Axis = BihNode.LeafAxis, Child = start, Count = count };
    }

    private static Point3D With(Point3D p, int axis, double value) => axis switch
    {
        0 => new Point3D(value, p.y, p.z),
        1 => new Point3D(p.x, value, p.z),
        _ => new Point3D(p.x, p.y, value),
    };
}
