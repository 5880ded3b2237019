using System.Runtime.CompilerServices;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Solvers;

/// <summary>
/// Möller–Trumbore ray–triangle test, shared by stand-alone triangles, mesh triangles and the
/// acceleration structures so that all of them report bit-identical t. Its terms are generated from
/// the GMacDSL macro MollerTrumboreTerms, as are those of the four-lane test
/// (<see cref="Kernels.TriangleGroupSolver"/>): the same operations in the same order.
/// </summary>
public static class TriangleSolver
{
    /// <summary>
    /// Hit with t in (<see cref="Ray.tMin"/>, tMax). Outputs the barycentric
    /// coordinates of v1 (beta) and v2 (gamma).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Intersect(
        in Ray ray, in Point3D v0, in Vector3D e1, in Vector3D e2, double tMax,
        out double t, out double beta, out double gamma)
    {
        TriangleTestCounters.MollerTrumbore.Increment();
        var d = ray.d;
        var s = ray.o - v0;
        double det, bn, gn, tn;

        #region GMac : MollerTrumboreTerms
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("s", "Vector3D", s);
        //GMac.Bind("e1", "Vector3D", e1);
        //GMac.Bind("e2", "Vector3D", e2);
        //GMac.Bind("det.1", "<det>");
        //GMac.Bind("bn.1", "<bn>");
        //GMac.Bind("gn.1", "<gn>");
        //GMac.Bind("tn.1", "<tn>");
        double tmp0 = d.x * e2.y - d.y * e2.x;
        double tmp1 = d.x * e2.z - d.z * e2.x;
        double tmp2 = d.y * e2.z - e2.y * d.z;
        double tmp3 = s.x * e1.y - s.y * e1.x;
        double tmp4 = s.x * e1.z - s.z * e1.x;
        double tmp5 = s.y * e1.z - s.z * e1.y;
        det = tmp0 * e1.z + tmp2 * e1.x - tmp1 * e1.y;
        bn = tmp0 * s.z + tmp2 * s.x - tmp1 * s.y;
        gn = tmp3 * d.z + tmp5 * d.x - tmp4 * d.y;
        tn = tmp3 * e2.z + tmp5 * e2.x - tmp4 * e2.y;
        #endregion

        t = beta = gamma = 0;
        if (det == 0)
        {
            return false; // ray parallel to the triangle's plane
        }

        double inv = 1.0 / det;
        beta = bn * inv;
        gamma = gn * inv;
        if (beta < 0 || beta > 1 || gamma < 0 || beta + gamma > 1)
        {
            return false;
        }

        t = tn * inv;
        return t > ray.tMin && t < tMax;
    }

    /// <summary>
    /// Same test and arithmetic as <see cref="Intersect"/>, returning the distance or +∞ on a miss.
    /// Without out parameters the JIT keeps everything in registers, which matters in traversal loops.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Distance(in Ray ray, in Point3D v0, in Vector3D e1, in Vector3D e2, double tMax)
    {
        TriangleTestCounters.MollerTrumbore.Increment();
        var d = ray.d;
        var s = ray.o - v0;
        double det, bn, gn, tn;

        #region GMac : MollerTrumboreTerms
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("s", "Vector3D", s);
        //GMac.Bind("e1", "Vector3D", e1);
        //GMac.Bind("e2", "Vector3D", e2);
        //GMac.Bind("det.1", "<det>");
        //GMac.Bind("bn.1", "<bn>");
        //GMac.Bind("gn.1", "<gn>");
        //GMac.Bind("tn.1", "<tn>");
        double tmp0 = d.x * e2.y - d.y * e2.x;
        double tmp1 = d.x * e2.z - d.z * e2.x;
        double tmp2 = d.y * e2.z - e2.y * d.z;
        double tmp3 = s.x * e1.y - s.y * e1.x;
        double tmp4 = s.x * e1.z - s.z * e1.x;
        double tmp5 = s.y * e1.z - s.z * e1.y;
        det = tmp0 * e1.z + tmp2 * e1.x - tmp1 * e1.y;
        bn = tmp0 * s.z + tmp2 * s.x - tmp1 * s.y;
        gn = tmp3 * d.z + tmp5 * d.x - tmp4 * d.y;
        tn = tmp3 * e2.z + tmp5 * e2.x - tmp4 * e2.y;
        #endregion

        if (det == 0)
        {
            return double.PositiveInfinity;
        }

        double inv = 1.0 / det;
        double beta = bn * inv, gamma = gn * inv;
        if (beta < 0 || beta > 1 || gamma < 0 || beta + gamma > 1)
        {
            return double.PositiveInfinity;
        }

        double t = tn * inv;
        return t > ray.tMin && t < tMax ? t : double.PositiveInfinity;
    }
}
