using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayTracer.Tracing;

namespace RayTracer.Kernels;

/// <summary>
/// The Möller–Trumbore test on four triangles at once. Each lane does the arithmetic of
/// <see cref="Geometry.Solvers.TriangleSolver.Distance"/> in the same order (the terms are generated
/// from the GMacDSL macro MollerTrumboreTerms), so every lane's distance is bit-identical to the
/// scalar test's and the acceleration structures agree exactly with brute force.
/// </summary>
internal static class TriangleGroupSolver
{
    /// <summary>The ray broadcast to four lanes: direction, origin and its bounds on t.</summary>
    internal readonly struct RayLanes(in Ray ray)
    {
        public readonly Vector3x4 D = new()
        {
            x = Vector256.Create(ray.d.x), y = Vector256.Create(ray.d.y), z = Vector256.Create(ray.d.z),
        };

        public readonly Vector3x4 O = new()
        {
            x = Vector256.Create(ray.o.x), y = Vector256.Create(ray.o.y), z = Vector256.Create(ray.o.z),
        };

        public readonly Vector256<double> TMin = Vector256.Create(ray.tMin);
    }

    /// <summary>Per lane, the hit distance in (tMin, tMax), or +∞.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector256<double> Distances(in RayLanes ray, ref TriangleGroup4 group, Vector256<double> tMax)
    {
        var d = ray.D;
        var e1 = group.E1;
        var e2 = group.E2;
        var s = new Vector3x4 { x = ray.O.x - group.V0.x, y = ray.O.y - group.V0.y, z = ray.O.z - group.V0.z };
        Vector256<double> det, bn, gn, tn;

        // The generated region names its temporaries' vector type.
#pragma warning disable IDE0007
        #region GMac : MollerTrumboreTerms
        //GMac.Type("Vector256<double>");
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
        var inv = Vector256<double>.One / det;
        var beta = bn * inv;
        var gamma = gn * inv;
        var t = tn * inv;
        var zero = Vector256<double>.Zero;
        var one = Vector256<double>.One;
        var miss = Vector256.Equals(det, zero)
            | Vector256.LessThan(beta, zero) | Vector256.GreaterThan(beta, one)
            | Vector256.LessThan(gamma, zero) | Vector256.GreaterThan(beta + gamma, one);
        var hit = Vector256.AndNot(Vector256.GreaterThan(t, ray.TMin) & Vector256.LessThan(t, tMax), miss);
        return Vector256.ConditionalSelect(hit, t, Vector256.Create(double.PositiveInfinity));
    }
}
