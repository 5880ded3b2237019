using System.Runtime.CompilerServices;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Solvers;

/// <summary>
/// The algebraic ray–triangle test of the ray tracer's base book (Suffern, Ray Tracing from the Ground
/// Up, §19.3): the ray and the plane equations solved by Cramer's rule for (beta, gamma, t), rejecting
/// on beta, then gamma, then their sum. Takes v0 and the edges e1 = v1 − v0, e2 = v2 − v0.
/// </summary>
public static class AlgebraicTriangleSolver
{
    /// <summary>Hit with t in (<see cref="Ray.tMin"/>, tMax), with the barycentrics of v1 (beta) and v2 (gamma).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Intersect(
        in Ray ray, in Point3D v0, in Vector3D e1, in Vector3D e2, double tMax,
        out double t, out double beta, out double gamma)
    {
        t = Hit(ray, v0, e1, e2, tMax, out beta, out gamma);
        return t < double.PositiveInfinity;
    }

    /// <summary>The hit distance below tMax, or +∞.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Distance(in Ray ray, in Point3D v0, in Vector3D e1, in Vector3D e2, double tMax) =>
        Hit(ray, v0, e1, e2, tMax, out _, out _);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Hit(
        in Ray ray, in Point3D v0, in Vector3D e1, in Vector3D e2, double tMax, out double beta, out double gamma)
    {
        TriangleTestCounters.Algebraic.Increment();
        beta = gamma = 0;
        // The book's names: columns (v0 − v1, v0 − v2, d) and the right side v0 − o.
        double a = -e1.x, b = -e2.x, c = ray.d.x, d = v0.x - ray.o.x;
        double e = -e1.y, f = -e2.y, g = ray.d.y, h = v0.y - ray.o.y;
        double i = -e1.z, j = -e2.z, k = ray.d.z, l = v0.z - ray.o.z;
        double m = f * k - g * j, n = h * k - g * l, p = f * l - h * j;
        double q = g * i - e * k, s = e * j - f * i;
        double denominator = a * m + b * q + c * s;
        if (denominator == 0)
            return double.PositiveInfinity; // ray parallel to the plane
        double inv = 1.0 / denominator;
        beta = (d * m - b * n - c * p) * inv;
        if (beta < 0)
            return double.PositiveInfinity;
        double r = e * l - h * i;
        gamma = (a * n + d * q + c * r) * inv;
        if (gamma < 0 || beta + gamma > 1)
            return double.PositiveInfinity;
        double t = (a * p - b * r + d * s) * inv;
        return t > ray.tMin && t < tMax ? t : double.PositiveInfinity;
    }
}
