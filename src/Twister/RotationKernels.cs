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
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = axis.y * d.z - axis.z * d.y;
        double tmp3 = axis.z * d.x - axis.x * d.z;
        double tmp4 = axis.x * d.y - axis.y * d.x;
        double tmp5 = tmp0 - 1.0;
        y.x = tmp2 * tmp1 + d.x + tmp5 * (tmp3 * axis.z - tmp4 * axis.y);
        y.y = tmp3 * tmp1 + d.y + tmp5 * (tmp4 * axis.x - tmp2 * axis.z);
        y.z = tmp4 * tmp1 + d.z + tmp5 * (tmp2 * axis.y - tmp3 * axis.x);
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
        var (tmp1, tmp0) = Math.SinCos(angle);
        double tmp2 = tmp0 - 1.0;
        double tmp3 = b.xy * axis.z + b.zx * axis.y;
        double tmp4 = b.yz * axis.x + tmp3;
        y.xy = tmp1 * (axis.x * b.zx - axis.y * b.yz) + b.xy + tmp2 * (b.xy - axis.z * tmp4);
        y.yz = tmp1 * (axis.y * b.xy - axis.z * b.zx) + b.yz + tmp2 * (b.yz * (axis.y * axis.y + axis.z * axis.z) - axis.x * tmp3);
        y.zx = tmp1 * (axis.z * b.yz - axis.x * b.xy) + b.zx + tmp2 * (b.zx - axis.y * tmp4);
        #endregion

        return y;
    }
}
