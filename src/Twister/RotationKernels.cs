namespace Twister;

/// <summary>
/// Rotation of directions and tangent planes about a unit axis: what a rotation and a full twist
/// (whose slide moves no direction) do to them, generated once for both.
/// </summary>
internal static class RotationKernels
{
    public static TwistableVector Rotate(TwistableVector axis, double angle, TwistableVector d)
    {
        var y = new TwistableVector();

        #region GMac : RotationTwistVector
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("d", "Vector3D", d);
        //GMac.Bind("y", "Vector3D", y);
        double tmp0 = axis.y * d.z - axis.z * d.y;
        double tmp1 = axis.z * d.x - axis.x * d.z;
        double tmp2 = axis.x * d.y - axis.y * d.x;
        double tmp3 = Math.Cos(angle) - 1.0;
        double tmp4 = Math.Sin(angle);
        y.x = tmp0 * tmp4 + d.x - (tmp2 * axis.y - tmp1 * axis.z) * tmp3;
        y.y = tmp1 * tmp4 + d.y - (tmp0 * axis.z - tmp2 * axis.x) * tmp3;
        y.z = tmp2 * tmp4 + d.z - (tmp1 * axis.x - tmp0 * axis.y) * tmp3;
        #endregion

        return y;
    }


    public static TwistableBivector Rotate(TwistableVector axis, double angle, TwistableBivector b)
    {
        var y = new TwistableBivector();

        #region GMac : RotationTwistBivector
        //GMac.Bind("axis", "Vector3D", axis);
        //GMac.Bind("angle.1", angle);
        //GMac.Bind("b", "Bivector3D", b);
        //GMac.Bind("y", "Bivector3D", y);
        double tmp0 = Math.Cos(angle);
        double tmp1 = Math.Sin(angle);
        double tmp2 = b.xy * axis.z + b.yz * axis.x + b.zx * axis.y;
        double tmp3 = tmp2 - tmp2 * tmp0;
        double tmp4 = b.yz * axis.y - b.zx * axis.x;
        y.xy = axis.z * tmp3 + b.xy * tmp0 - tmp1 * tmp4;
        double tmp5 = tmp0 - 1.0;
        double tmp6 = b.xy * axis.x - b.yz * axis.z;
        y.yz = axis.y * (tmp5 * tmp4 + b.xy * tmp1) + axis.z * (-(tmp5 * tmp6) - b.zx * tmp1) + b.yz;
        y.zx = axis.y * tmp3 + b.zx * tmp0 - tmp1 * tmp6;
        #endregion

        return y;
    }
}
