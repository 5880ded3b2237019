using System.Runtime.CompilerServices;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Solvers;

/// <summary>
/// The Plücker ray–triangle test of thesis §6.6.3, its arithmetic generated from dsl/macros/plucker.gmac.
/// The signed distances d1, d2, d3 of the ray to the edge lines v0v1, v1v2, v2v0 must share one sign;
/// two are computed first so that most misses leave early. Then d_i / (d1 + d2 + d3) are the
/// barycentrics (d1 weights v2, d2 weights v0, d3 weights v1) and t = tn / (d1 + d2 + d3).
/// </summary>
public static class PluckerTriangleSolver
{
    /// <summary>Hit with t in (<see cref="Ray.tMin"/>, tMax), with the barycentrics of v1 (beta) and v2 (gamma).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Intersect(
        in Ray ray, in Point3D v0, in Point3D v1, in Point3D v2, double tMax,
        out double t, out double beta, out double gamma)
    {
        t = Hit(ray, v0, v1, v2, tMax, out beta, out gamma);
        return t < double.PositiveInfinity;
    }

    /// <summary>The hit distance below tMax, or +∞.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Distance(in Ray ray, in Point3D v0, in Point3D v1, in Point3D v2, double tMax) =>
        Hit(ray, v0, v1, v2, tMax, out _, out _);

    /// <summary>The same test on stored edge lines and plane (<see cref="PluckerTriangle.From"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Intersect(in Ray ray, in PluckerTriangle triangle, double tMax, out double t, out double beta, out double gamma)
    {
        t = Hit(ray, RayLine(ray), triangle, tMax, out beta, out gamma);
        return t < double.PositiveInfinity;
    }

    /// <summary>
    /// The test on stored lines given the ray's line (<see cref="RayLine"/>), which a traversal builds
    /// once per ray. Same arithmetic as <see cref="Intersect(in Ray, in PluckerTriangle, double, out double, out double, out double)"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Distance(in Ray ray, in PluckerLine rayLine, in PluckerTriangle triangle, double tMax) =>
        Hit(ray, rayLine, triangle, tMax, out _, out _);

    /// <summary>The ray as the line (o + eo) ∧ d, generated from RayLine (6.15).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static PluckerLine RayLine(in Ray ray)
    {
        var lr = new PluckerLine();

        #region GMac : RayLine
        //GMac.Bind("pr", "PgaVector3D", ray.o);
        //GMac.Bind("vr", "PgaVector3D", ray.d);
        //GMac.Bind("line", "PluckerLine", lr);
        lr.xy = ray.o.x * ray.d.y - ray.o.y * ray.d.x;
        lr.yz = ray.o.y * ray.d.z - ray.o.z * ray.d.y;
        lr.xz = ray.o.x * ray.d.z - ray.o.z * ray.d.x;
        lr.xo = -ray.d.x;
        lr.yo = -ray.d.y;
        lr.zo = -ray.d.z;
        #endregion

        return lr;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Hit(
        in Ray ray, in Point3D v0, in Point3D v1, in Point3D v2, double tMax, out double beta, out double gamma)
    {
        TriangleTestCounters.Plucker.Increment();
        beta = gamma = 0;
        // Seen from the ray's origin (pr = 0, left unbound): the generator folds the ray's line to
        // eo ∧ d, and each d_i to a triple product of d with two vertices.
        Vector3D a = v0 - ray.o, b = v1 - ray.o, c = v2 - ray.o;
        double d1, d2;

        #region GMac : PluckerRayTriangle
        //GMac.Bind("vr", "PgaVector3D", ray.d);
        //GMac.Bind("v1", "PgaVector3D", a);
        //GMac.Bind("v2", "PgaVector3D", b);
        //GMac.Bind("v3", "PgaVector3D", c);
        //GMac.Bind("d1.1", "<d1>");
        //GMac.Bind("d2.1", "<d2>");
        //GMac.Bind("pr.e1", "0");
        //GMac.Bind("pr.e2", "0");
        //GMac.Bind("pr.e3", "0");
        double tmp0 = b.x * ray.d.y - b.y * ray.d.x;
        double tmp1 = b.z * ray.d.x - b.x * ray.d.z;
        double tmp2 = b.z * ray.d.y - b.y * ray.d.z;
        d1 = a.x * tmp2 - a.y * tmp1 - a.z * tmp0;
        d2 = c.y * tmp1 + c.z * tmp0 - c.x * tmp2;
        #endregion

        if ((d1 < 0 && d2 > 0) || (d1 > 0 && d2 < 0))
            return double.PositiveInfinity;
        double d3;

        #region GMac : PluckerRayTriangle
        //GMac.Bind("vr", "PgaVector3D", ray.d);
        //GMac.Bind("v1", "PgaVector3D", a);
        //GMac.Bind("v2", "PgaVector3D", b);
        //GMac.Bind("v3", "PgaVector3D", c);
        //GMac.Bind("d3.1", "<d3>");
        //GMac.Bind("pr.e1", "0");
        //GMac.Bind("pr.e2", "0");
        //GMac.Bind("pr.e3", "0");
        d3 = ray.d.x * (c.z * a.y - c.y * a.z) + ray.d.y * (a.z * c.x - c.z * a.x) + ray.d.z * (c.y * a.x - a.y * c.x);
        #endregion

        if (!SameSide(d1, d2, d3))
            return double.PositiveInfinity;
        double tn;

        #region GMac : PluckerRayTriangle
        //GMac.Bind("vr", "PgaVector3D", ray.d);
        //GMac.Bind("v1", "PgaVector3D", a);
        //GMac.Bind("v2", "PgaVector3D", b);
        //GMac.Bind("v3", "PgaVector3D", c);
        //GMac.Bind("tn.1", "<tn>");
        //GMac.Bind("pr.e1", "0");
        //GMac.Bind("pr.e2", "0");
        //GMac.Bind("pr.e3", "0");
        double t0 = a.y - c.y;
        double t1 = c.x - a.x;
        double t2 = a.z - c.z;
        tn = (b.x - a.x) * (t0 * a.z - t2 * a.y) + (b.y - a.y) * (t1 * a.z + t2 * a.x) - (b.z - a.z) * (t1 * a.y + t0 * a.x);
        #endregion

        return Finish(d1, d2, d3, tn, ray.tMin, tMax, out beta, out gamma);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Hit(in Ray ray, in PluckerLine lr, in PluckerTriangle triangle, double tMax, out double beta, out double gamma)
    {
        TriangleTestCounters.PluckerEdges.Increment();
        beta = gamma = 0;
        double d1, d2;

        #region GMac : PluckerRayTriangleLines
        //GMac.Bind("lr", "PluckerLine", lr);
        //GMac.Bind("l1", "PluckerLine", triangle.L1);
        //GMac.Bind("l2", "PluckerLine", triangle.L2);
        //GMac.Bind("d1.1", "<d1>");
        //GMac.Bind("d2.1", "<d2>");
        //GMac.Bind("pr.e1", "0");
        //GMac.Bind("pr.e2", "0");
        //GMac.Bind("pr.e3", "0");
        //GMac.Bind("l3.e1^e2", "0");
        //GMac.Bind("l3.e1^e3", "0");
        //GMac.Bind("l3.e2^e3", "0");
        //GMac.Bind("l3.e1^eo", "0");
        //GMac.Bind("l3.e2^eo", "0");
        //GMac.Bind("l3.e3^eo", "0");
        //GMac.Bind("plane.e1^e2^e3", "0");
        //GMac.Bind("plane.e1^e2^eo", "0");
        //GMac.Bind("plane.e1^e3^eo", "0");
        //GMac.Bind("plane.e2^e3^eo", "0");
        d1 = lr.xy * triangle.L1.zo + lr.yz * triangle.L1.xo + lr.xo * triangle.L1.yz + lr.zo * triangle.L1.xy - triangle.L1.yo * lr.xz - lr.yo * triangle.L1.xz;
        d2 = lr.xy * triangle.L2.zo + lr.yz * triangle.L2.xo + triangle.L2.xy * lr.zo + triangle.L2.yz * lr.xo - triangle.L2.xz * lr.yo - triangle.L2.yo * lr.xz;
        #endregion

        if ((d1 < 0 && d2 > 0) || (d1 > 0 && d2 < 0))
            return double.PositiveInfinity;
        double d3;

        #region GMac : PluckerRayTriangleLines
        //GMac.Bind("pr", "PgaVector3D", ray.o);
        //GMac.Bind("lr", "PluckerLine", lr);
        //GMac.Bind("l3", "PluckerLine", triangle.L3);
        //GMac.Bind("d3.1", "<d3>");
        //GMac.Bind("l1.e1^e2", "0");
        //GMac.Bind("l1.e1^e3", "0");
        //GMac.Bind("l1.e2^e3", "0");
        //GMac.Bind("l1.e1^eo", "0");
        //GMac.Bind("l1.e2^eo", "0");
        //GMac.Bind("l1.e3^eo", "0");
        //GMac.Bind("l2.e1^e2", "0");
        //GMac.Bind("l2.e1^e3", "0");
        //GMac.Bind("l2.e2^e3", "0");
        //GMac.Bind("l2.e1^eo", "0");
        //GMac.Bind("l2.e2^eo", "0");
        //GMac.Bind("l2.e3^eo", "0");
        //GMac.Bind("plane.e1^e2^e3", "0");
        //GMac.Bind("plane.e1^e2^eo", "0");
        //GMac.Bind("plane.e1^e3^eo", "0");
        //GMac.Bind("plane.e2^e3^eo", "0");
        d3 = triangle.L3.yz * lr.xo + triangle.L3.xo * lr.yz + triangle.L3.zo * lr.xy + lr.zo * triangle.L3.xy - triangle.L3.xz * lr.yo - triangle.L3.yo * lr.xz;
        #endregion

        if (!SameSide(d1, d2, d3))
            return double.PositiveInfinity;
        double tn;

        #region GMac : PluckerRayTriangleLines
        //GMac.Bind("pr", "PgaVector3D", ray.o);
        //GMac.Bind("plane", "PluckerPlane", triangle.Plane);
        //GMac.Bind("tn.1", "<tn>");
        //GMac.Bind("lr.e1^e2", "0");
        //GMac.Bind("lr.e1^e3", "0");
        //GMac.Bind("lr.e2^e3", "0");
        //GMac.Bind("lr.e1^eo", "0");
        //GMac.Bind("lr.e2^eo", "0");
        //GMac.Bind("lr.e3^eo", "0");
        //GMac.Bind("l1.e1^e2", "0");
        //GMac.Bind("l1.e1^e3", "0");
        //GMac.Bind("l1.e2^e3", "0");
        //GMac.Bind("l1.e1^eo", "0");
        //GMac.Bind("l1.e2^eo", "0");
        //GMac.Bind("l1.e3^eo", "0");
        //GMac.Bind("l2.e1^e2", "0");
        //GMac.Bind("l2.e1^e3", "0");
        //GMac.Bind("l2.e2^e3", "0");
        //GMac.Bind("l2.e1^eo", "0");
        //GMac.Bind("l2.e2^eo", "0");
        //GMac.Bind("l2.e3^eo", "0");
        //GMac.Bind("l3.e1^e2", "0");
        //GMac.Bind("l3.e1^e3", "0");
        //GMac.Bind("l3.e2^e3", "0");
        //GMac.Bind("l3.e1^eo", "0");
        //GMac.Bind("l3.e2^eo", "0");
        //GMac.Bind("l3.e3^eo", "0");
        tn = ray.o.x * triangle.Plane.yzo + ray.o.z * triangle.Plane.xyo - ray.o.y * triangle.Plane.xzo - triangle.Plane.xyz;
        #endregion

        return Finish(d1, d2, d3, tn, ray.tMin, tMax, out beta, out gamma);
    }

    /// <summary>The third distance against the first two, which already agree.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool SameSide(double d1, double d2, double d3) =>
        !((d3 < 0 && (d1 > 0 || d2 > 0)) || (d3 > 0 && (d1 < 0 || d2 < 0)));

    /// <summary>(6.19) and (6.20) with one division, once the ray is known to pass through the triangle.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Finish(double d1, double d2, double d3, double tn, double tMin, double tMax, out double beta, out double gamma)
    {
        beta = gamma = 0;
        double sum = d1 + d2 + d3;
        if (sum == 0)
            return double.PositiveInfinity; // ray parallel to the plane, or the triangle degenerate
        double inv = 1.0 / sum;
        double t = tn * inv;
        if (!(t > tMin && t < tMax))
            return double.PositiveInfinity;
        beta = d3 * inv;
        gamma = d1 * inv;
        return t;
    }
}
