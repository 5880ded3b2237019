using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Tracing;

namespace RayTracer.Kernels;

/// <summary>
/// The Möller–Trumbore test on eight triangles at once with <see cref="Vector512{T}"/>: the arithmetic
/// of <see cref="TriangleGroupSolver"/> (terms generated from the same GMacDSL macro, the checks in the
/// same order), so every lane's distance is bit-identical to the scalar test's.
/// </summary>
internal static class TriangleGroup8Solver
{
    /// <summary>The ray broadcast to eight lanes: direction, origin and its lower bound on t.</summary>
    internal readonly struct RayLanes(in Ray ray)
    {
        public readonly Vector3x8 D = new()
        {
            x = Vector512.Create(ray.d.x), y = Vector512.Create(ray.d.y), z = Vector512.Create(ray.d.z),
        };

        public readonly Vector3x8 O = new()
        {
            x = Vector512.Create(ray.o.x), y = Vector512.Create(ray.o.y), z = Vector512.Create(ray.o.z),
        };

        public readonly Vector512<double> TMin = Vector512.Create(ray.tMin);
    }

    /// <summary>Per lane, the hit distance in (tMin, tMax), or +∞.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector512<double> Distances(in RayLanes ray, ref TriangleGroup8 group, Vector512<double> tMax)
    {
        var d = ray.D;
        var e1 = group.E1;
        var e2 = group.E2;
        var s = new Vector3x8 { x = ray.O.x - group.V0.x, y = ray.O.y - group.V0.y, z = ray.O.z - group.V0.z };
        Vector512<double> det, bn, gn, tn;

        // The generated region names its temporaries' vector type.
#pragma warning disable IDE0007
        #region GMac : MollerTrumboreTerms
        //GMac.Type("Vector512<double>");
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("s", "Vector3D", s);
        //GMac.Bind("e1", "Vector3D", e1);
        //GMac.Bind("e2", "Vector3D", e2);
        //GMac.Bind("det.1", "<det>");
        //GMac.Bind("bn.1", "<bn>");
        //GMac.Bind("gn.1", "<gn>");
        //GMac.Bind("tn.1", "<tn>");
        var tmp0 = d.x * e2.y - d.y * e2.x;
        var tmp1 = d.x * e2.z - d.z * e2.x;
        var tmp2 = d.y * e2.z - e2.y * d.z;
        var tmp3 = s.x * e1.y - s.y * e1.x;
        var tmp4 = s.x * e1.z - s.z * e1.x;
        var tmp5 = s.y * e1.z - s.z * e1.y;
        det = tmp0 * e1.z + tmp2 * e1.x - tmp1 * e1.y;
        bn = tmp0 * s.z + tmp2 * s.x - tmp1 * s.y;
        gn = tmp3 * d.z + tmp5 * d.x - tmp4 * d.y;
        tn = tmp3 * e2.z + tmp5 * e2.x - tmp4 * e2.y;
        #endregion
#pragma warning restore IDE0007

        // The scalar test's early exits as masks, written so that NaN lanes pass or fail as they do there.
        var inv = Vector512<double>.One / det;
        var beta = bn * inv;
        var gamma = gn * inv;
        var t = tn * inv;
        var zero = Vector512<double>.Zero;
        var one = Vector512<double>.One;
        var miss = Vector512.Equals(det, zero)
            | Vector512.LessThan(beta, zero) | Vector512.GreaterThan(beta, one)
            | Vector512.LessThan(gamma, zero) | Vector512.GreaterThan(beta + gamma, one);
        var hit = Vector512.AndNot(Vector512.GreaterThan(t, ray.TMin) & Vector512.LessThan(t, tMax), miss);
        return Vector512.ConditionalSelect(hit, t, Vector512.Create(double.PositiveInfinity));
    }
}
