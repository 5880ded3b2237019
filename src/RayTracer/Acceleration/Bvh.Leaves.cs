using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Kernels;
using RayTracer.Tracing;

namespace RayTracer.Acceleration;

/// <summary>
/// What the four- and eight-wide nearest-hit traversals share once their children are pushed: the pop to the
/// next interior node and the leaves on the way, tested through their lane groups of one width (<see cref="Groups4"/>,
/// <see cref="Groups8"/>, struct type arguments, so each traversal compiles to its own width's vector code) or one
/// primitive at a time. The any-hit traversals keep their leaf tests inline: through a shared helper, the four-wide
/// one measured 4 % slower on shadow rays (its broadcast far bound no longer stayed in a register).
/// </summary>
public sealed partial class Bvh
{
    /// <summary>How one ray meets the lane groups of a leaf, for one group width.</summary>
    private interface ILaneGroups
    {
        /// <summary>The nearest hit among the leaf's groups below <paramref name="t"/>; lanes in index order, ties to the lower index.</summary>
        bool Nearest(in BvhLeaf leaf, ref double t, ref int primitive);
    }

    /// <summary>The primitives of a leaf without a lane group, tested one by one; true when one is nearer than <paramref name="t"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool NearestInLeaf(PrimitiveTable table, in BvhLeaf leaf, in Ray ray, ref double t, ref int primitive)
    {
        bool hit = false;
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

        return hit;
    }

    /// <summary>
    /// The lanes set in <paramref name="found"/> (distances from <paramref name="distances"/> on), in index
    /// order with a strict test so ties go to the lower index as in the scalar loop; true when one is nearer.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool NearestLane(int found, ref double distances, int firstPrimitive, ref double t, ref int primitive)
    {
        bool hit = false;
        while (found != 0)
        {
            int lane = BitOperations.TrailingZeroCount(found);
            found &= found - 1;
            double ti = Unsafe.Add(ref distances, lane);
            if (ti < t)
            {
                t = ti;
                primitive = firstPrimitive + lane;
                hit = true;
            }
        }

        return hit;
    }

    /// <summary>
    /// Pops entries until an interior node to descend into, skipping those entered beyond the nearest hit
    /// and testing leaves on the way; the node, or -1 when the stack has run out.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int PopToInterior<TGroups>(in TGroups groups, BvhLeaf[] leaves, PrimitiveTable table, in Ray ray,
        Span<int> stackRef, Span<double> stackEnter, ref int sp, ref double t, ref int primitive, ref bool hit)
        where TGroups : struct, ILaneGroups
    {
        while (sp != 0)
        {
            sp--;
            if (stackEnter[sp] > t * FarSlack)
            {
                continue;
            }

            int reference = stackRef[sp];
            if (reference >= 0)
            {
                return reference;
            }

            ref var leaf = ref leaves[~reference];
            hit |= leaf.Group >= 0 ? groups.Nearest(in leaf, ref t, ref primitive) : NearestInLeaf(table, in leaf, in ray, ref t, ref primitive);
        }

        return -1;
    }

    /// <summary>Four-lane groups (<see cref="TriangleGroup4"/>, <see cref="Vector256{T}"/>).</summary>
    private readonly struct Groups4(TriangleGroup4[] groups, in Ray ray) : ILaneGroups
    {
        private readonly TriangleGroupSolver.RayLanes _lanes = new(ray);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Nearest(in BvhLeaf leaf, ref double t, ref int primitive)
        {
            bool hit = false;
            for (int g = 0; g < leaf.GroupCount; g++)
            {
                var tMax = Vector256.Create(t);
                var tv = TriangleGroupSolver.Distances(_lanes, ref groups[leaf.Group + g], tMax);
                int found = (int)Vector256.LessThan(tv, tMax).ExtractMostSignificantBits();
                hit |= NearestLane(found, ref Unsafe.As<Vector256<double>, double>(ref tv), leaf.First + 4 * g, ref t, ref primitive);
            }

            return hit;
        }
    }

    /// <summary>Eight-lane groups (<see cref="TriangleGroup8"/>, <see cref="Vector512{T}"/>).</summary>
    private readonly struct Groups8(AlignedArray<TriangleGroup8> groups, in Ray ray) : ILaneGroups
    {
        private readonly TriangleGroup8Solver.RayLanes _lanes = new(ray);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Nearest(in BvhLeaf leaf, ref double t, ref int primitive)
        {
            bool hit = false;
            for (int g = 0; g < leaf.GroupCount; g++)
            {
                var tMax = Vector512.Create(t);
                var tv = TriangleGroup8Solver.Distances(_lanes, ref groups[leaf.Group + g], tMax);
                int found = (int)Vector512.LessThan(tv, tMax).ExtractMostSignificantBits();
                hit |= NearestLane(found, ref Unsafe.As<Vector512<double>, double>(ref tv), leaf.First + 8 * g, ref t, ref primitive);
            }

            return hit;
        }
    }
}
