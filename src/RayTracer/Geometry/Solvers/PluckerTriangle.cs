using RayTracer.Maths;

namespace RayTracer.Geometry.Solvers;

/// <summary>
/// What the Plücker test with stored edge lines keeps per triangle: the lines v0v1, v1v2, v2v0 and the
/// plane, 22 doubles (176 bytes) against the 9 of a vertex-and-edges triangle.
/// </summary>
public struct PluckerTriangle
{
    public PluckerLine L1;
    public PluckerLine L2;
    public PluckerLine L3;
    public PluckerPlane Plane;

    /// <summary>The lines and plane of (v0, v1, v2), generated from PluckerTriangleLines.</summary>
    public static PluckerTriangle From(in Point3D v0, in Point3D v1, in Point3D v2)
    {
        var l1 = new PluckerLine();
        var l2 = new PluckerLine();
        var l3 = new PluckerLine();
        var plane = new PluckerPlane();

        #region GMac : PluckerTriangleLines
        //GMac.Bind("v1", "PgaVector3D", v0);
        //GMac.Bind("v2", "PgaVector3D", v1);
        //GMac.Bind("v3", "PgaVector3D", v2);
        //GMac.Bind("l1", "PluckerLine", l1);
        //GMac.Bind("l2", "PluckerLine", l2);
        //GMac.Bind("l3", "PluckerLine", l3);
        //GMac.Bind("plane", "PluckerPlane", plane);
        double tmp0 = v0.y - v1.y;
        double tmp1 = v0.x - v1.x;
        l1.xy = tmp1 * v0.y - tmp0 * v0.x;
        double tmp2 = v0.z - v1.z;
        l1.yz = tmp0 * v0.z - tmp2 * v0.y;
        l1.xz = tmp1 * v0.z - tmp2 * v0.x;
        l1.xo = tmp1;
        l1.yo = tmp0;
        l1.zo = tmp2;
        double tmp3 = v1.y - v2.y;
        double tmp4 = v1.x - v2.x;
        l2.xy = tmp4 * v1.y - tmp3 * v1.x;
        double tmp5 = v1.z - v2.z;
        l2.yz = tmp3 * v1.z - tmp5 * v1.y;
        l2.xz = tmp4 * v1.z - tmp5 * v1.x;
        l2.xo = tmp4;
        l2.yo = tmp3;
        l2.zo = tmp5;
        double tmp6 = v2.y - v0.y;
        double tmp7 = v2.x - v0.x;
        double tmp8 = v0.y * tmp7 - v0.x * tmp6;
        l3.xy = tmp8;
        double tmp9 = v2.z - v0.z;
        double tmp10 = v0.z * tmp6 - v0.y * tmp9;
        l3.yz = tmp10;
        double tmp11 = v0.z * tmp7 - v0.x * tmp9;
        l3.xz = tmp11;
        l3.xo = tmp7;
        l3.yo = tmp6;
        l3.zo = tmp9;
        plane.xyz = tmp0 * tmp11 - (tmp1 * tmp10 + tmp2 * tmp8);
        plane.xyo = tmp7 * tmp0 - tmp1 * tmp6;
        plane.yzo = tmp6 * tmp2 - tmp0 * tmp9;
        plane.xzo = tmp7 * tmp2 - tmp1 * tmp9;
        #endregion

        return new PluckerTriangle { L1 = l1, L2 = l2, L3 = l3, Plane = plane };
    }
}
