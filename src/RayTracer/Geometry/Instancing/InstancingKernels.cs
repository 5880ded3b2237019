using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Geometry.Instancing;

/// <summary>The set-up steps of TSR and RSTR instances, generated from dsl/macros/instancing.gmac.</summary>
internal static class InstancingKernels
{
    /// <summary>The unit axis and the angle (radians) of a unit rotor; the identity gets the axis e2 and angle 0.</summary>
    public static (Vector3D Axis, double Angle) AxisAngle(Rotor3D r)
    {
        if (r.xy * r.xy + r.yz * r.yz + r.zx * r.zx == 0)
            return (Vector3D.UnitY, 0);
        var axis = new Vector3D();
        double angle;

        #region GMac : RotorAxisAngle
        //GMac.Bind("r", "Rotor3D", r);
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("angle.1", "<angle>");
        double tmp0 = Math.Sqrt(r.yz * r.yz + r.xy * r.xy + r.zx * r.zx);
        double tmp1 = -1.0 / tmp0;
        angle = 2.0 * Math.Atan2(tmp0, r.s);
        axis.x = r.yz * tmp1;
        axis.y = r.zx * tmp1;
        axis.z = r.xy * tmp1;
        #endregion

        return (axis, angle);
    }

    /// <summary>
    /// The unit normal of the mirror taking the unit <paramref name="v"/> onto e2. Below the plane
    /// y = 0 the plain difference v − e2 is well conditioned and the kernel's 1 + vy is not; at e2
    /// itself any mirror through the y axis will do, and e1 is taken.
    /// </summary>
    public static Vector3D MirrorNormalOntoY(Vector3D v)
    {
        if (v.y < 0)
            return (v - Vector3D.UnitY).Normalized();
        if (v.x == 0 && v.z == 0)
            return Vector3D.UnitX;
        var m = new Vector3D();

        #region GMac : RstrMirrorNormal
        //GMac.Bind("v", "Vector3D", v);
        //GMac.Bind("m", "Vector3D", m);
        double tmp0 = v.x * v.x + v.z * v.z;
        double tmp1 = -(tmp0 / (v.y + 1.0));
        double tmp2 = 1.0 / Math.Sqrt(tmp1 * tmp1 + tmp0);
        m.x = v.x * tmp2;
        m.y = tmp1 * tmp2;
        m.z = v.z * tmp2;
        #endregion

        return m;
    }
}
