namespace Twister;

/// <summary>
/// A full twist (thesis §6.4, Figure 6-6): a rotation by <see cref="Angle"/> about the line through
/// <see cref="AxisOrigin"/> along <see cref="Axis"/>, followed by a slide of <see cref="Translation"/>
/// times <see cref="Axis"/> along it. The body of <see cref="Apply"/> is generated from the GMacDSL
/// macro ApplyTwistToPoint3D (conformal versor V_t V_GR applied to the point).
/// </summary>
public sealed class Twist(TwistablePoint axisOrigin, TwistablePoint axis, double angle, double translation)
{
    public TwistablePoint AxisOrigin { get; } = axisOrigin;
    public TwistablePoint Axis { get; } = axis;
    public double Angle { get; } = angle;
    public double Translation { get; } = translation;

    public TwistablePoint Apply(TwistablePoint p)
    {
        var origin = AxisOrigin;
        var axis = Axis;
        var cr = Angle;
        var ct = Translation;
        var result = new TwistablePoint();

        #region GMac : ApplyTwistToPoint3D
        //GMac.Bind("rot_axis", "Vector3D", axis);
        //GMac.Bind("tr_origin", "Vector3D", origin);
        //GMac.Bind("angle.1", cr);
        //GMac.Bind("tr_param.1", ct);
        //GMac.Bind("in_mv", "Vector3D", p);
        //GMac.Bind("out_mv", "Vector3D", result);
        double tmp0 = 0.5 * ct;
        double tmp1 = -(axis.x * tmp0);
        double tmp2 = -(axis.y * tmp0);
        double tmp3 = -(axis.z * tmp0);
        double tmp4 = 0.5 * cr;
        double tmp5 = Math.Cos(tmp4);
        double tmp6 = Math.Sin(tmp4) / Math.Sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
        double tmp7 = -(axis.z * tmp6);
        double tmp8 = axis.y * tmp6;
        double tmp9 = -(axis.x * tmp6);
        double tmp10 = origin.z - tmp3;
        double tmp11 = origin.y - tmp2;
        double tmp12 = tmp7 * tmp11 + tmp8 * tmp10 + tmp1 * tmp5;
        double tmp13 = tmp1 - origin.x;
        double tmp14 = tmp9 * tmp10 + tmp7 * tmp13 + tmp2 * tmp5;
        double tmp15 = tmp8 * tmp13 + tmp3 * tmp5 - tmp9 * tmp11;
        double tmp16 = tmp1 * tmp9 + tmp3 * tmp7 - tmp2 * tmp8;
        double tmp17 = p.x * tmp5;
        double tmp18 = p.z * tmp8;
        double tmp19 = p.y * tmp7;
        double tmp20 = p.x * tmp8;
        double tmp21 = 2.0 * tmp15;
        double tmp22 = p.x * tmp7;
        double tmp23 = 2.0 * tmp14;
        double tmp24 = p.y * tmp8;
        double tmp25 = p.z * tmp7;
        double tmp26 = tmp12 - tmp19;
        result.x = tmp9 * (2.0 * (tmp25 - tmp16 - tmp24) + tmp9 * p.x) + tmp5 * (2.0 * (tmp18 - tmp26) + tmp17) + tmp7 * (-tmp23 - tmp22) + tmp8 * (-tmp21 - tmp20);
        double tmp27 = 2.0 * tmp16;
        double tmp28 = p.y * tmp5;
        double tmp29 = p.z * tmp5;
        result.y = tmp9 * (2.0 * (tmp29 - tmp15 - tmp20) - tmp9 * p.y) + tmp7 * (2.0 * (tmp12 - tmp17 - tmp18) - tmp19) + tmp5 * (tmp28 - tmp23) + tmp8 * (tmp27 + tmp24);
        result.z = tmp9 * (2.0 * (tmp14 + tmp22 - tmp28) - tmp9 * p.z) + tmp8 * (2.0 * (tmp26 - tmp17) - tmp18) + tmp5 * (tmp29 - tmp21) + tmp7 * (tmp25 - tmp27);
        #endregion

        return result;
    }
}
