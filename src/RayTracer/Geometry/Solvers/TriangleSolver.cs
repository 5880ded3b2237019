using System.Runtime.CompilerServices;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Geometry.Solvers;

/// <summary>
/// Möller–Trumbore ray–triangle test, shared by stand-alone triangles, mesh triangles and the
/// acceleration structures' triangle fast path so that all of them report bit-identical t.
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
        // p = d × e2
        double px = ray.d.y * e2.z - ray.d.z * e2.y;
        double py = ray.d.z * e2.x - ray.d.x * e2.z;
        double pz = ray.d.x * e2.y - ray.d.y * e2.x;
        double det = e1.x * px + e1.y * py + e1.z * pz;
        t = beta = gamma = 0;
        if (det == 0)
        {
            return false; // ray parallel to the triangle's plane
        }

        double inv = 1.0 / det;
        double sx = ray.o.x - v0.x, sy = ray.o.y - v0.y, sz = ray.o.z - v0.z;
        beta = (sx * px + sy * py + sz * pz) * inv;
        if (beta < 0 || beta > 1)
        {
            return false;
        }

        // q = s × e1
        double qx = sy * e1.z - sz * e1.y;
        double qy = sz * e1.x - sx * e1.z;
        double qz = sx * e1.y - sy * e1.x;
        gamma = (ray.d.x * qx + ray.d.y * qy + ray.d.z * qz) * inv;
        if (gamma < 0 || beta + gamma > 1)
        {
            return false;
        }

        t = (e2.x * qx + e2.y * qy + e2.z * qz) * inv;
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
        double px = ray.d.y * e2.z - ray.d.z * e2.y;
        double py = ray.d.z * e2.x - ray.d.x * e2.z;
        double pz = ray.d.x * e2.y - ray.d.y * e2.x;
        double det = e1.x * px + e1.y * py + e1.z * pz;
        if (det == 0)
        {
            return double.PositiveInfinity;
        }

        double inv = 1.0 / det;
        double sx = ray.o.x - v0.x, sy = ray.o.y - v0.y, sz = ray.o.z - v0.z;
        double beta = (sx * px + sy * py + sz * pz) * inv;
        if (beta < 0 || beta > 1)
        {
            return double.PositiveInfinity;
        }

        double qx = sy * e1.z - sz * e1.y;
        double qy = sz * e1.x - sx * e1.z;
        double qz = sx * e1.y - sy * e1.x;
        double gamma = (ray.d.x * qx + ray.d.y * qy + ray.d.z * qz) * inv;
        if (gamma < 0 || beta + gamma > 1)
        {
            return double.PositiveInfinity;
        }

        double t = (e2.x * qx + e2.y * qy + e2.z * qz) * inv;
        return t > ray.tMin && t < tMax ? t : double.PositiveInfinity;
    }
}
