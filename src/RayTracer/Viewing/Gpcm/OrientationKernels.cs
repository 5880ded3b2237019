using RayTracer.Maths;

namespace RayTracer.Viewing;

/// <summary>The rotor steps of the camera orientation of Figure 6-14, generated from dsl/macros/gpcm.gmac.</summary>
internal static class OrientationKernels
{
    /// <summary>The rotor taking unit <paramref name="a"/> onto unit <paramref name="b"/>; meaningless when b = −a.</summary>
    public static Rotor3D RotorOnto(Vector3D a, Vector3D b)
    {
        var r = new Rotor3D();

        #region GMac : RotorOntoUnitVector
        //GMac.Bind("a", "Vector3D", a);
        //GMac.Bind("b", "Vector3D", b);
        //GMac.Bind("r", "Rotor3D", r);
        double tmp0 = a.y * b.x - a.x * b.y;
        double tmp1 = a.x * b.z - a.z * b.x;
        double tmp2 = a.z * b.y - a.y * b.z;
        double tmp3 = a.x * b.x + a.y * b.y + a.z * b.z + 1.0;
        double tmp4 = 1.0 / Math.Sqrt(tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2 + tmp3 * tmp3);
        r.s = tmp3 * tmp4;
        r.xy = tmp0 * tmp4;
        r.yz = tmp2 * tmp4;
        r.zx = tmp1 * tmp4;
        #endregion

        return r;
    }

    /// <summary>A half turn about the unit <paramref name="axis"/>.</summary>
    public static Rotor3D HalfTurn(Vector3D axis)
    {
        var r = new Rotor3D();

        #region GMac : HalfTurnRotor
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("r", "Rotor3D", r);
        r.s = 0.0;
        r.xy = axis.z;
        r.yz = axis.x;
        r.zx = axis.y;
        #endregion

        return r;
    }

    /// <summary>The part of <paramref name="d"/> perpendicular to the unit vector <paramref name="n"/>.</summary>
    public static Vector3D Rejection(Vector3D d, Vector3D n)
    {
        var p = new Vector3D();

        #region GMac : RejectionFromUnitVector
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("n", "Vector3D", n);
        //GMac.Bind("p", "Vector3D", p);
        double tmp0 = d.x * n.y - d.y * n.x;
        double tmp1 = d.z * n.x - d.x * n.z;
        double tmp2 = d.y * n.z - d.z * n.y;
        p.x = tmp0 * n.y - tmp1 * n.z;
        p.y = tmp2 * n.z - tmp0 * n.x;
        p.z = tmp1 * n.x - tmp2 * n.y;
        #endregion

        return p;
    }

    /// <summary>The rotation <paramref name="r1"/> followed by <paramref name="r2"/>.</summary>
    public static Rotor3D Compose(Rotor3D r2, Rotor3D r1)
    {
        var r = new Rotor3D();

        #region GMac : ComposeRotors
        //GMac.Bind("r2", "Rotor3D", r2);
        //GMac.Bind("r1", "Rotor3D", r1);
        //GMac.Bind("r", "Rotor3D", r);
        r.s = r2.s * r1.s - r2.xy * r1.xy - r2.yz * r1.yz - r2.zx * r1.zx;
        r.xy = r2.s * r1.xy + r2.xy * r1.s + r2.zx * r1.yz - r2.yz * r1.zx;
        r.yz = r2.s * r1.yz + r2.xy * r1.zx + r2.yz * r1.s - r2.zx * r1.xy;
        r.zx = r2.s * r1.zx + r2.yz * r1.xy + r2.zx * r1.s - r2.xy * r1.yz;
        #endregion

        return r;
    }

    /// <summary>The images of e1, e2 and e3 under the unit rotor <paramref name="r"/>.</summary>
    public static void Axes(Rotor3D r, out Vector3D right, out Vector3D up, out Vector3D back)
    {
        var x = new Vector3D();
        var y = new Vector3D();
        var z = new Vector3D();

        #region GMac : CameraAxes
        //GMac.Bind("r", "Rotor3D", r);
        //GMac.Bind("right", "Vector3D", x);
        //GMac.Bind("up", "Vector3D", y);
        //GMac.Bind("back", "Vector3D", z);
        double tmp0 = r.yz + r.yz;
        double tmp1 = r.xy + r.xy;
        double tmp2 = r.zx + r.zx;
        double tmp3 = r.zx * tmp2;
        double tmp4 = r.xy * tmp1;
        x.x = 1.0 - tmp4 - tmp3;
        double tmp5 = r.yz * tmp2;
        double tmp6 = r.s * tmp1;
        x.y = tmp5 - tmp6;
        double tmp7 = r.xy * tmp0;
        double tmp8 = r.s * tmp2;
        x.z = tmp8 + tmp7;
        y.x = tmp6 + tmp5;
        double tmp9 = r.yz * tmp0;
        y.y = 1.0 - tmp4 - tmp9;
        double tmp10 = r.xy * tmp2;
        double tmp11 = r.s * tmp0;
        y.z = tmp10 - tmp11;
        z.x = tmp7 - tmp8;
        z.y = tmp11 + tmp10;
        z.z = 1.0 - tmp9 - tmp3;
        #endregion

        right = x;
        up = y;
        back = z;
    }
}
