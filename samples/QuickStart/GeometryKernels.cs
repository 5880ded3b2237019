namespace QuickStart;

/// <summary>
/// Three formulas whose bodies GMac generates at build time from the macros of the DSL library
/// (the lines between the //GMac. lines and #endregion are rewritten by `gmac generate`).
/// </summary>
public static class GeometryKernels
{
    /// <summary>w = (u ∧ v) ⌋ I⁻¹: the normal to two vectors (thesis §4.10.1).</summary>
    public static Vec3 NormalToVectors(Vec3 u, Vec3 v)
    {
        double wx, wy, wz;

        #region GMac : NormalToVectors
        //GMac.Bind("u", "Vector3D", u);
        //GMac.Bind("v.e1", "<v.x>");
        //GMac.Bind("v.e2", "<v.y>");
        //GMac.Bind("v.e3", "<v.z>");
        //GMac.Bind("w.e1", "<wx>");
        //GMac.Bind("w.e2", "<wy>");
        //GMac.Bind("w.e3", "<wz>");
        wx = u.y * v.z - u.z * v.y;
        wy = u.z * v.x - u.x * v.z;
        wz = u.x * v.y - u.y * v.x;
        #endregion

        return new Vec3(wx, wy, wz);
    }

    /// <summary>
    /// The sphere through four points in the conformal model: σ = p1 ∧ p2 ∧ p3 ∧ p4 and its dual
    /// ω = α(no + c + ½(c² − r²) ni), from which the centre c and radius r are read.
    /// </summary>
    public static (Vec3 Centre, double Radius) SphereThroughPoints(Vec3 a, Vec3 b, Vec3 c, Vec3 d)
    {
        double sNo, sX, sY, sZ, sNi;

        #region GMac : SphereThroughPoints
        //GMac.Bind("p1", "ConformalPoint3D", a);
        //GMac.Bind("p2", "ConformalPoint3D", b);
        //GMac.Bind("p3", "ConformalPoint3D", c);
        //GMac.Bind("p4", "ConformalPoint3D", d);
        //GMac.Bind("omega.no", "<sNo>");
        //GMac.Bind("omega.e1", "<sX>");
        //GMac.Bind("omega.e2", "<sY>");
        //GMac.Bind("omega.e3", "<sZ>");
        //GMac.Bind("omega.ni", "<sNi>");
        double tmp0 = b.x - a.x;
        double tmp1 = b.y - a.y;
        double tmp2 = b.z - a.z;
        double tmp3 = 0.5 * (tmp0 * tmp0 + tmp1 * tmp1 + tmp2 * tmp2);
        double tmp4 = c.x - a.x;
        double tmp5 = c.y - a.y;
        double tmp6 = c.z - a.z;
        double tmp7 = 0.5 * (tmp4 * tmp4 + tmp5 * tmp5 + tmp6 * tmp6);
        double tmp8 = d.x - a.x;
        double tmp9 = d.y - a.y;
        double tmp10 = tmp9 * tmp4 - tmp8 * tmp5;
        double tmp11 = d.z - a.z;
        double tmp12 = 0.5 * (tmp8 * tmp8 + tmp9 * tmp9 + tmp11 * tmp11);
        double tmp13 = tmp12 * tmp4 - tmp8 * tmp7;
        double tmp14 = tmp12 * tmp5 - tmp9 * tmp7;
        double tmp15 = tmp13 * tmp1 - (tmp14 * tmp0 + tmp3 * tmp10);
        double tmp16 = tmp12 * tmp6 - tmp11 * tmp7;
        double tmp17 = tmp11 * tmp4 - tmp8 * tmp6;
        double tmp18 = tmp16 * tmp0 + tmp3 * tmp17 - tmp13 * tmp2;
        double tmp19 = tmp11 * tmp5 - tmp9 * tmp6;
        double tmp20 = tmp1 * tmp17 - (tmp19 * tmp0 + tmp2 * tmp10);
        double tmp21 = tmp18 + tmp20 * a.y;
        sY = tmp21;
        double tmp22 = tmp20 * a.z + tmp15;
        sZ = tmp22;
        sNo = tmp20;
        double tmp23 = tmp19 * tmp3 + tmp16 * tmp1 - tmp14 * tmp2;
        double tmp24 = tmp20 * a.x - tmp23;
        sX = tmp24;
        sNi = 0.5 * (a.x * (tmp24 - tmp23) + a.y * (tmp18 + tmp21) + a.z * (tmp22 + tmp15));
        #endregion

        var centre = new Vec3(sX / sNo, sY / sNo, sZ / sNo);
        return (centre, Math.Sqrt(centre.Dot(centre) - 2 * sNi / sNo));
    }

    /// <summary>
    /// Rotation of a point by an angle about the axis through a point: the Figure 6-6 twist with
    /// its slide bound to the constant 0, which GMac folds away.
    /// </summary>
    public static Vec3 RotateAboutLine(Vec3 point, Vec3 through, Vec3 axis, double angle)
    {
        var result = new Vec3();

        #region GMac : ApplyTwistToPoint3D
        //GMac.Bind("rot_axis", "Vector3D", axis);
        //GMac.Bind("tr_origin", "Vector3D", through);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("tr_param.1", "0");
        //GMac.Bind("in_mv", "Vector3D", point);
        //GMac.Bind("out_mv", "Vector3D", result);
        double tmp0 = axis.z * axis.z + axis.y * axis.y + axis.x * axis.x;
        double tmp1 = 1.0 / tmp0;
        double tmp2 = Math.Sqrt(tmp1);
        var (tmp4, tmp3) = Math.SinCos(angle);
        double tmp5 = 1.0 - tmp3;
        double tmp6 = point.y - through.y;
        double tmp7 = point.x - through.x;
        double tmp8 = point.z - through.z;
        double tmp9 = tmp2 * tmp6;
        double tmp10 = tmp2 * tmp8;
        double tmp11 = (tmp8 * axis.z + axis.x * tmp7 + axis.y * tmp6) * tmp1;
        result.x = tmp4 * (axis.y * tmp10 - axis.z * tmp9) + point.x - tmp5 * (tmp7 - axis.x * tmp11);
        double tmp12 = tmp2 * tmp7;
        result.y = tmp4 * (axis.z * tmp12 - axis.x * tmp10) + point.y - tmp5 * (tmp6 - axis.y * tmp11);
        result.z = tmp4 * (axis.x * tmp9 - axis.y * tmp12) + point.z - tmp5 * (tmp8 - axis.z * tmp11);
        #endregion

        return result;
    }
}
