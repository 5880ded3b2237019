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
        var (tmp5, tmp3) = Math.SinCos(angle);
        double tmp4 = tmp3 - 1.0;
        y.x = tmp0 * tmp5 + d.x + tmp4 * (tmp1 * axis.z - tmp2 * axis.y);
        y.y = tmp1 * tmp5 + d.y + tmp4 * (tmp2 * axis.x - tmp0 * axis.z);
        y.z = tmp2 * tmp5 + d.z + tmp4 * (tmp0 * axis.y - tmp1 * axis.x);
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
        var (tmp2, tmp0) = Math.SinCos(angle);
        double tmp1 = tmp0 - 1.0;
        double tmp3 = b.xy * axis.z + b.zx * axis.y;
        double tmp4 = b.yz * axis.x + tmp3;
        y.xy = tmp2 * (axis.x * b.zx - axis.y * b.yz) + b.xy + tmp1 * (b.xy - axis.z * tmp4);
        y.yz = tmp2 * (axis.y * b.xy - axis.z * b.zx) + b.yz + tmp1 * (b.yz * (axis.y * axis.y + axis.z * axis.z) - axis.x * tmp3);
        y.zx = tmp2 * (axis.z * b.yz - axis.x * b.xy) + b.zx + tmp1 * (b.zx - axis.y * tmp4);
        #endregion

        return y;
    }
}
