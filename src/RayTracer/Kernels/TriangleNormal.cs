using RayTracer.Maths;

namespace RayTracer.Kernels;

/// <summary>
/// The normal of a triangle as (v1 − v0) ∧ (v2 − v0) ⌋ I⁻¹, the cross product written in geometric
/// algebra (thesis §4.10). The body is generated from the GMacDSL macro NormalToVectors.
/// </summary>
internal static class TriangleNormal
{
    /// <summary>The unnormalized normal of triangle (v0, v1, v2); its length is twice the triangle's area.</summary>
    public static Normal3D Of(Point3D v0, Point3D v1, Point3D v2) => OfEdges(v1 - v0, v2 - v0);

    /// <summary>
    /// The unnormalized normal of the triangle with edges <paramref name="u"/> = v1 − v0 and
    /// <paramref name="v"/> = v2 − v0, for callers that already hold the edges.
    /// </summary>
    public static Normal3D OfEdges(Vector3D u, Vector3D v)
    {
        var n = new Normal3D();

        #region GMac : NormalToVectors
        //GMac.Bind("u", "Vector3D", u);
        //GMac.Bind("v", "Vector3D", v);
        //GMac.Bind("w", "Normal3D", n);
        n.x = u.y * v.z - u.z * v.y;
        n.y = u.z * v.x - u.x * v.z;
        n.z = u.x * v.y - u.y * v.x;
        #endregion

        return n;
    }
}
