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
        double tmp0 = v0.x - v1.x;
        double tmp1 = v0.y - v1.y;
        double tmp2 = v0.z - v1.z;
        double tmp3 = v2.x - v0.x;
        double tmp4 = v2.y - v0.y;
        double tmp5 = v2.z - v0.z;
        double tmp6 = tmp3 * tmp1 - tmp4 * tmp0;
        double tmp7 = tmp3 * tmp2 - tmp5 * tmp0;
        double tmp8 = tmp4 * tmp2 - tmp5 * tmp1;
        l1.xy = v0.x * v1.y - v0.y * v1.x;
        l1.yz = v0.y * v1.z - v0.z * v1.y;
        l1.xz = v0.x * v1.z - v0.z * v1.x;
        l1.xo = tmp0;
        l1.yo = tmp1;
        l1.zo = tmp2;
        l2.xy = v1.x * v2.y - v1.y * v2.x;
        l2.yz = v1.y * v2.z - v1.z * v2.y;
        l2.xz = v1.x * v2.z - v1.z * v2.x;
        l2.xo = v1.x - v2.x;
        l2.yo = v1.y - v2.y;
        l2.zo = v1.z - v2.z;
        l3.xy = v0.y * v2.x - v0.x * v2.y;
        l3.yz = v0.z * v2.y - v0.y * v2.z;
        l3.xz = v0.z * v2.x - v0.x * v2.z;
        l3.xo = tmp3;
        l3.yo = tmp4;
        l3.zo = tmp5;
        plane.xyz = tmp6 * v0.z + tmp8 * v0.x - tmp7 * v0.y;
        plane.xyo = tmp6;
        plane.yzo = tmp8;
        plane.xzo = tmp7;
        #endregion

        return new PluckerTriangle { L1 = l1, L2 = l2, L3 = l3, Plane = plane };
    }
}
