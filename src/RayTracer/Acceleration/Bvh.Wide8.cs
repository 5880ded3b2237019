using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Kernels;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// The traversal of eight-wide nodes (<see cref="Bvh8Node"/>, one <see cref="Vector512{T}"/> box test per
/// node) and eight-lane leaf groups (<see cref="TriangleGroup8"/>): the four-wide traversal's order and
/// skips, with fewer levels to descend.
/// </summary>
public sealed partial class Bvh
{
    // Each eight-wide level pushes at most seven entries beyond the one it pops.
    private const int StackSize8 = 7 * MaxDepth + 8;

    /// <summary>Nearest hit over eight-wide nodes; <typeparamref name="TOrigin"/> as in <see cref="Nearest{TOrigin}"/>.</summary>
    [SkipLocalsInit]
    private bool Nearest8<TOrigin>(in Ray ray, ref double t, ref int primitive)
        where TOrigin : struct, IOrigin
    {
        var r = new WideRay8(ray);
        var max = TOrigin.Moved ? WideRay8.MaxOf(ray) : default;
        ref var nodes = ref _wide8.First;
        var leaves = _leaves;
        var groups = new Groups8(_groups8, ray);
        var table = Table;
        Span<int> stackRef = stackalloc int[StackSize8];
        Span<double> stackEnter = stackalloc double[StackSize8];
        int sp = 0;
        bool hit = false;
        int current = 0;

        while (true)
        {
            ref var node = ref Unsafe.Add(ref nodes, current);
            int mask = r.Hits<TOrigin>(ref node, t, in max, out var enter);

            // A single interior child needs no trip through the stack.
            if (mask != 0 && (mask & (mask - 1)) == 0)
            {
                int only = Child(ref node, BitOperations.TrailingZeroCount(mask));
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
                int child = Child(ref node, lane);
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
    /// Any hit over eight-wide nodes, children in node order (ordering them by distance cost more than it
    /// saved in the four-wide traversal). The first child entered is visited next without a trip through the
    /// stack, and a leaf as soon as it is found.
    /// </summary>
    [SkipLocalsInit]
    private bool Any8<TOrigin>(in Ray ray, double tMax)
        where TOrigin : struct, IOrigin
    {
        var r = new WideRay8(ray);
        var max = TOrigin.Moved ? WideRay8.MaxOf(ray) : default;
        ref var nodes = ref _wide8.First;
        var leaves = _leaves;
        var groups = _groups8;
        var lanes = new TriangleGroup8Solver.RayLanes(ray);
        var table = Table;
        var tMaxLanes = Vector512.Create(tMax);
        Span<int> stackRef = stackalloc int[StackSize8];
        int sp = 0;
        int reference = 0;

        while (true)
        {
            if (reference >= 0)
            {
                ref var node = ref Unsafe.Add(ref nodes, reference);
                int mask = r.Hits<TOrigin>(ref node, tMax, in max, out _);
                if (mask != 0)
                {
                    reference = Child(ref node, BitOperations.TrailingZeroCount(mask));
                    mask &= mask - 1;
                    while (mask != 0)
                    {
                        int lane = BitOperations.TrailingZeroCount(mask);
                        mask &= mask - 1;
                        stackRef[sp++] = Child(ref node, lane);
                    }

                    continue;
                }
            }
            else
            {
                ref var leaf = ref leaves[~reference];
                if (leaf.Group >= 0 && leaf.GroupsCastShadows)
                {
                    for (int g = 0; g < leaf.GroupCount; g++)
                    {
                        if (Vector512.LessThanAny(TriangleGroup8Solver.Distances(lanes, ref groups[leaf.Group + g], tMaxLanes), tMaxLanes))
                        {
                            return true;
                        }
                    }
                }
                else
                {
                    for (int i = leaf.First, end = leaf.First + leaf.Count; i < end; i++)
                    {
                        if (table.Occludes(i, ray, tMax))
                        {
                            return true;
                        }
                    }
                }
            }

            if (sp == 0)
            {
                return false;
            }

            reference = stackRef[--sp];
        }
    }

    /// <summary>
    /// Child reference by lane. A <c>switch</c> rather than a load indexed by the lane: the processor
    /// predicts the jump and loads the next node before the box test that chooses it has finished.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Child(ref Bvh8Node node, int lane) => lane switch
    {
        0 => node.Child0,
        1 => node.Child1,
        2 => node.Child2,
        3 => node.Child3,
        4 => node.Child4,
        5 => node.Child5,
        6 => node.Child6,
        _ => node.Child7,
    };

    /// <summary>The maximum planes' origins of a ray that does not move along some axis, in eight lanes.</summary>
    private readonly record struct MaxOrigins8(Vector512<double> X, Vector512<double> Y, Vector512<double> Z);

    /// <summary>Ray broadcast into vectors for testing eight boxes at once; the arithmetic of <see cref="WideRay"/>.</summary>
    private readonly struct WideRay8
    {
        private readonly Vector512<double> _ox, _oy, _oz, _ix, _iy, _iz;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public WideRay8(in Ray ray)
        {
            _ox = Vector512.Create(WideRay.Origins(ray.o.x, ray.d.x).Min);
            _oy = Vector512.Create(WideRay.Origins(ray.o.y, ray.d.y).Min);
            _oz = Vector512.Create(WideRay.Origins(ray.o.z, ray.d.z).Min);
            _ix = Vector512.Create(WideRay.Reciprocal(ray.d.x));
            _iy = Vector512.Create(WideRay.Reciprocal(ray.d.y));
            _iz = Vector512.Create(WideRay.Reciprocal(ray.d.z));
        }

        public static MaxOrigins8 MaxOf(in Ray ray) => new(
            Vector512.Create(WideRay.Origins(ray.o.x, ray.d.x).Max),
            Vector512.Create(WideRay.Origins(ray.o.y, ray.d.y).Max),
            Vector512.Create(WideRay.Origins(ray.o.z, ray.d.z).Max));

        /// <summary>Bit i set when the segment [0, tMax] meets child box i; <paramref name="enter"/> holds the entry distances.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public int Hits<TOrigin>(ref Bvh8Node node, double tMax, in MaxOrigins8 max, out Vector512<double> enter)
            where TOrigin : struct, IOrigin
        {
            var mx = TOrigin.Moved ? max.X : _ox;
            var my = TOrigin.Moved ? max.Y : _oy;
            var mz = TOrigin.Moved ? max.Z : _oz;
            Vector512<double> ax = (node.MinX - _ox) * _ix, bx = (node.MaxX - mx) * _ix;
            Vector512<double> ay = (node.MinY - _oy) * _iy, by = (node.MaxY - my) * _iy;
            Vector512<double> az = (node.MinZ - _oz) * _iz, bz = (node.MaxZ - mz) * _iz;
            var t0 = Vector512.MaxNative(
                Vector512.MaxNative(Vector512.MinNative(ax, bx), Vector512.MinNative(ay, by)),
                Vector512.MaxNative(Vector512.MinNative(az, bz), Vector512<double>.Zero));
            var t1 = Vector512.MinNative(
                Vector512.MinNative(Vector512.MaxNative(ax, bx), Vector512.MaxNative(ay, by)),
                Vector512.MinNative(Vector512.MaxNative(az, bz), Vector512.Create(tMax)));
            enter = t0;
            return (int)Vector512.LessThanOrEqual(t0, t1 * Vector512.Create(FarSlack)).ExtractMostSignificantBits() & node.ValidMask;
        }
    }
}
