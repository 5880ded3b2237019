using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>
/// ga-benchmark's conformal inverse-kinematics chain (dsl/macros/inverse-kinematics.gmac): five
/// joint angles, rotors about moved joint axes and one translator, to the gripper's position.
/// </summary>
public sealed class InverseKinematicsKernel : GaKernel<JointAngles, Vec3>
{
    public override string MacroName => "InverseKinematics";
    public override string Source => "ga-benchmark, conformal inverse kinematics";

    /// <summary>
    /// Counted by hand from <see cref="Hand"/>: 4 rotations about a line (Rodrigues 12 mul, 10 add,
    /// t = p − R p 9 mul, 9 add, a SinCos counted as 2 calls) and R1's SinCos; 3 composed motions
    /// (36 mul, 27 add each); 5 points moved (9 mul, 9 add each); R1 applied by hand to J1 and J2
    /// (4 mul) and the difference T2 (3 add).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 205, Multiplications: 241, Divisions: 0, Calls: 10);

    private static readonly Vec3 J1 = new(200, 0, 680);
    private static readonly Vec3 J2 = new(200, 0, 1570);
    private static readonly Vec3 J3 = new(1080, 0, 1720);
    private static readonly Vec3 Jg = new(1334.2, 0, 1720);

    protected override JointAngles CreateInput(Random random) => new()
    {
        A1 = Signed(random) * Math.PI, A2 = Signed(random) * Math.PI, A3 = Signed(random) * Math.PI,
        A4 = Signed(random) * Math.PI, A5 = Signed(random) * Math.PI,
    };

    protected override double[] Components(Vec3 v) => [v.x, v.y, v.z];

    protected override void RunGenerated(JointAngles[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(JointAngles[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(JointAngles[] inputs, Vec3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in JointAngles x, out Vec3 p)
    {
        #region GMac : InverseKinematics
        //GMac.Bind("a1.1", "<x.A1>");
        //GMac.Bind("a2.1", "<x.A2>");
        //GMac.Bind("a3.1", "<x.A3>");
        //GMac.Bind("a4.1", "<x.A4>");
        //GMac.Bind("a5.1", "<x.A5>");
        //GMac.Bind("gripper", "Point3D", "p");
        double tmp0 = 0.5 * x.A1;
        var (tmp1, tmp2) = Math.SinCos(tmp0);
        double tmp3 = 0.5 * x.A2;
        var (tmp4, tmp16) = Math.SinCos(tmp3);
        double tmp5 = tmp1 * tmp1;
        double tmp6 = tmp2 * tmp2;
        double tmp7 = tmp5 - tmp6;
        double tmp8 = tmp7 * tmp4;
        double tmp9 = -(tmp1 * tmp2);
        double tmp10 = tmp9 * tmp4;
        double tmp11 = -2.0 * tmp10;
        double tmp12 = -680.0 * tmp8;
        double tmp13 = -1360.0 * tmp10;
        double tmp14 = tmp6 + tmp5;
        double tmp15 = -200.0 * tmp4 * tmp14;
        double tmp17 = tmp2 * tmp16;
        double tmp18 = -(tmp1 * tmp16);
        double tmp19 = tmp1 * tmp11 - tmp2 * tmp8;
        double tmp20 = tmp1 * tmp8 + tmp2 * tmp11;
        double tmp21 = tmp1 * tmp13 + tmp2 * tmp12;
        double tmp22 = tmp2 * tmp15;
        double tmp23 = tmp1 * tmp15;
        double tmp24 = 0.5 * x.A3;
        var (tmp25, tmp28) = Math.SinCos(tmp24);
        double tmp26 = tmp25 * (tmp17 * tmp17 + tmp19 * tmp19 - tmp18 * tmp18 - tmp20 * tmp20);
        double tmp27 = 2.0 * tmp25 * (tmp19 * tmp20 - tmp17 * tmp18);
        double tmp29 = 2.0 * (tmp2 * tmp13 - tmp1 * tmp12);
        double tmp30 = tmp29 - 3140.0 * tmp20;
        double tmp31 = 2.0 * tmp21;
        double tmp32 = tmp19 * tmp22 - (3140.0 * tmp19 + 200.0 * tmp17 - tmp31) * tmp17;
        double tmp33 = tmp20 * tmp23 - (200.0 * tmp18 + tmp30) * tmp18;
        double tmp34 = 200.0 * tmp7 + tmp33 - tmp32;
        double tmp35 = -2.0 * tmp23 - 400.0 * tmp20;
        double tmp36 = tmp35 - 3140.0 * tmp18;
        double tmp37 = -400.0 * tmp18 - tmp30;
        double tmp38 = tmp17 * tmp37 + tmp19 * tmp36 + 2.0 * (tmp18 * tmp21 - tmp20 * tmp22) + 400.0 * tmp9;
        double tmp39 = (tmp31 - 1570.0 * tmp19) * tmp19 + (1570.0 * tmp17 - 400.0 * tmp19 - 2.0 * tmp22) * tmp17;
        double tmp40 = (tmp29 - 1570.0 * tmp20) * tmp20 - tmp18 * (tmp35 - 1570.0 * tmp18);
        double tmp41 = tmp40 - (1570.0 * tmp14 - tmp39);
        double tmp42 = tmp25 * (tmp39 - tmp40) - 0.5 * (tmp26 * tmp41 + tmp28 * tmp34);
        double tmp43 = tmp25 * (tmp17 * tmp36 + 2.0 * (tmp18 * tmp22 + tmp20 * tmp21) - tmp19 * tmp37) - 0.5 * (tmp27 * tmp41 + tmp28 * tmp38);
        double tmp44 = tmp25 * (tmp32 + tmp33) + 0.5 * (tmp26 * tmp34 + tmp27 * tmp38 - tmp28 * tmp41);
        double tmp45 = tmp2 * tmp28;
        double tmp46 = -(tmp1 * tmp28);
        double tmp47 = tmp1 * tmp27 + tmp2 * tmp26;
        double tmp48 = tmp2 * tmp27 - tmp1 * tmp26;
        double tmp49 = tmp1 * tmp43 + tmp2 * tmp42;
        double tmp50 = tmp2 * tmp43 - tmp1 * tmp42;
        double tmp51 = tmp2 * tmp44;
        double tmp52 = -(tmp1 * tmp44);
        double tmp53 = 0.5 * x.A4;
        var (tmp54, tmp66) = Math.SinCos(tmp53);
        double tmp55 = -2.0 * tmp54;
        double tmp56 = (tmp46 * tmp48 - tmp45 * tmp47) * tmp55;
        double tmp57 = (tmp45 * tmp46 + tmp47 * tmp48) * tmp55;
        double tmp58 = tmp54 * (tmp46 * tmp46 + tmp47 * tmp47 - tmp45 * tmp45 - tmp48 * tmp48);
        double tmp59 = 2.0 * tmp50;
        double tmp60 = 3440.0 * tmp48 - tmp59;
        double tmp61 = 2.0 * tmp52;
        double tmp62 = tmp54 * (tmp45 * (tmp61 - 3440.0 * tmp46) + tmp47 * tmp60 + 2.0 * (tmp46 * tmp51 - tmp48 * tmp49));
        double tmp63 = 2.0 * tmp49;
        double tmp64 = tmp54 * (tmp45 * (2.0 * tmp51 - 1720.0 * tmp45) + tmp46 * (1720.0 * tmp46 - tmp61) + tmp47 * (tmp63 - 1720.0 * tmp47) + tmp48 * (1720.0 * tmp48 - tmp59));
        double tmp65 = tmp54 * (tmp45 * tmp60 + tmp46 * (3440.0 * tmp47 - tmp63) - 2.0 * (tmp47 * tmp52 + tmp48 * tmp51));
        double tmp67 = tmp45 * tmp66 - tmp46 * tmp56 - tmp47 * tmp57 - tmp48 * tmp58;
        double tmp68 = tmp45 * tmp56 + tmp46 * tmp66 + tmp47 * tmp58 - tmp48 * tmp57;
        double tmp69 = tmp45 * tmp57 + tmp47 * tmp66 + tmp48 * tmp56 - tmp46 * tmp58;
        double tmp70 = tmp45 * tmp58 + tmp46 * tmp57 + tmp48 * tmp66 - tmp47 * tmp56;
        double tmp71 = tmp45 * tmp62 + tmp49 * tmp66 + tmp50 * tmp56 + tmp51 * tmp57 - tmp46 * tmp64 - tmp47 * tmp65 - tmp52 * tmp58;
        double tmp72 = tmp45 * tmp65 + tmp47 * tmp62 + tmp48 * tmp64 + tmp51 * tmp66 - tmp49 * tmp57 - tmp50 * tmp58 - tmp52 * tmp56;
        double tmp73 = 0.5 * x.A5;
        var (tmp74, tmp88) = Math.SinCos(tmp73);
        double tmp75 = 2.0 * tmp74;
        double tmp76 = (tmp67 * tmp70 + tmp68 * tmp69) * tmp75;
        double tmp77 = tmp74 * (tmp67 * tmp67 + tmp69 * tmp69 - tmp68 * tmp68 - tmp70 * tmp70);
        double tmp78 = (tmp69 * tmp70 - tmp67 * tmp68) * tmp75;
        double tmp79 = 2.0 * (tmp45 * tmp64 + tmp46 * tmp62 + tmp50 * tmp66 + tmp51 * tmp58 + tmp52 * tmp57 - tmp48 * tmp65 - tmp49 * tmp56);
        double tmp80 = 2.0 * (tmp46 * tmp65 + tmp48 * tmp62 + tmp49 * tmp58 + tmp51 * tmp56 + tmp52 * tmp66 - tmp47 * tmp64 - tmp50 * tmp57);
        double tmp81 = 2.0 * tmp71;
        double tmp82 = 2.0 * tmp72;
        double tmp83 = tmp80 - 2160.0 * tmp70;
        double tmp84 = tmp74 * (tmp67 * (1720.0 * tmp67 - 2160.0 * tmp69 - tmp82) + tmp68 * (tmp83 - 1720.0 * tmp68) + tmp69 * (tmp81 - 1720.0 * tmp69) + tmp70 * (1720.0 * tmp70 - tmp79));
        double tmp85 = tmp79 - 3440.0 * tmp70;
        double tmp86 = tmp74 * (tmp67 * (tmp83 - 3440.0 * tmp68) + tmp69 * (2160.0 * tmp68 + tmp85) + 2.0 * (tmp68 * tmp72 + tmp70 * tmp71));
        double tmp87 = tmp74 * (tmp70 * (1080.0 * tmp70 - tmp80) - (tmp68 * (1080.0 * tmp68 + tmp85) - tmp67 * (tmp81 - 1080.0 * tmp67 - 3440.0 * tmp69) - tmp69 * (1080.0 * tmp69 + tmp82)));
        double tmp89 = tmp48 * tmp78 - (tmp45 * tmp88 - tmp46 * tmp76 - tmp47 * tmp77);
        double tmp90 = tmp45 * tmp76 + tmp46 * tmp88 + tmp47 * tmp78 - tmp48 * tmp77;
        double tmp91 = tmp45 * tmp77 + tmp47 * tmp88 + tmp48 * tmp76 - tmp46 * tmp78;
        double tmp92 = tmp45 * tmp78 + tmp46 * tmp77 + tmp48 * tmp88 - tmp47 * tmp76;
        double tmp93 = tmp45 * tmp84 + tmp49 * tmp88 + tmp50 * tmp76 + tmp51 * tmp77 - tmp46 * tmp86 - tmp47 * tmp87 - tmp52 * tmp78;
        double tmp94 = tmp45 * tmp87 + tmp47 * tmp84 + tmp48 * tmp86 + tmp51 * tmp88 - tmp49 * tmp77 - tmp50 * tmp78 - tmp52 * tmp76;
        double tmp95 = 2.0 * (tmp46 * tmp87 + tmp48 * tmp84 + tmp49 * tmp78 + tmp51 * tmp76 + tmp52 * tmp88 - tmp47 * tmp86 - tmp50 * tmp77);
        double tmp96 = 2.0 * (tmp45 * tmp86 + tmp46 * tmp84 + tmp50 * tmp88 + tmp51 * tmp78 + tmp52 * tmp77 - tmp48 * tmp87 - tmp49 * tmp76);
        double tmp97 = 2.0 * tmp94;
        double tmp98 = 2.0 * tmp93;
        double tmp99 = tmp96 - 3440.0 * tmp92;
        p.x = tmp92 * (1334.2 * tmp92 - tmp95) - (tmp89 * (3440.0 * tmp91 - 1334.2 * tmp89 - tmp98) + tmp90 * (1334.2 * tmp90 + tmp99) + tmp91 * (tmp97 + 1334.2 * tmp91));
        double tmp100 = tmp95 - 2668.4 * tmp92;
        p.y = tmp89 * (2668.4 * tmp90 + tmp99) + tmp91 * (tmp100 - 3440.0 * tmp90) + 2.0 * (tmp93 * tmp90 - tmp94 * tmp92);
        p.z = tmp89 * (1720.0 * tmp89 + tmp97 + 2668.4 * tmp91) + tmp90 * (1720.0 * tmp90 - tmp100) + tmp91 * (tmp98 - 1720.0 * tmp91) + tmp92 * (tmp96 - 1720.0 * tmp92);
        #endregion
    }

    /// <summary>The same steps with the numeric engine.</summary>
    public static Vec3 Direct(in JointAngles x)
    {
        Multivector<double> Rotor(Multivector<double> line, double angle) => Math.Cos(angle / 2) * CgaOne + Math.Sin(angle / 2) * line;
        Multivector<double> DualLine(Multivector<double> a, Multivector<double> b) => a.Op(b).Op(CgaNi).Dual();
        var (j1, j2, j3, jg) = (Point(J1), Point(J2), Point(J3), Point(Jg));
        var r1 = Rotor(DualLine(CgaNo, Point(new Vec3(0, 0, 1))), x.A1);
        var r2 = Rotor(r1.Apply(DualLine(j1, Point(new Vec3(J1.x, 1, J1.z)))), x.A2);
        var r21 = r2.Gp(r1);
        var r3 = Rotor(r21.Apply(DualLine(j2, Point(new Vec3(J2.x, 1, J2.z)))), x.A3);
        var d = r21.Apply(j2) - r1.Apply(j2);
        var t2 = CgaOne - 0.5 * ConformalVector(ToVec3(d)).Op(CgaNi);
        var m3 = r3.Gp(t2).Gp(r1);
        var wrist = DualLine(j3, jg);
        var r4 = Rotor(m3.Apply(wrist / wrist.Norm()), x.A4);
        var rg = Rotor(r4.Gp(m3).Apply(DualLine(j3, Point(new Vec3(J3.x, 1, J3.z)))), x.A5);
        return ToVec3(rg.Gp(m3).Apply(jg));
    }

    /// <summary>A rigid motion x ↦ R x + t, R row-major.</summary>
    private struct Motion
    {
        public double R00, R01, R02, R10, R11, R12, R20, R21, R22, Tx, Ty, Tz;
    }

    /// <summary>The rotation by <paramref name="angle"/> about the line through p along the unit u (Rodrigues), as a motion.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Motion AboutLine(double px, double py, double pz, double ux, double uy, double uz, double angle)
    {
        var (s, c) = Math.SinCos(angle);
        var t = 1 - c;
        double tx = t * ux, ty = t * uy, tz = t * uz, sx = s * ux, sy = s * uy, sz = s * uz;
        double xy = tx * uy, yz = ty * uz, zx = tz * ux;
        var m = new Motion
        {
            R00 = tx * ux + c, R01 = xy - sz, R02 = zx + sy,
            R10 = xy + sz, R11 = ty * uy + c, R12 = yz - sx,
            R20 = zx - sy, R21 = yz + sx, R22 = tz * uz + c,
        };
        m.Tx = px - (m.R00 * px + m.R01 * py + m.R02 * pz);
        m.Ty = py - (m.R10 * px + m.R11 * py + m.R12 * pz);
        m.Tz = pz - (m.R20 * px + m.R21 * py + m.R22 * pz);
        return m;
    }

    /// <summary>a after b: R = Ra Rb, t = Ra tb + ta.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Motion After(in Motion a, in Motion b) => new()
    {
        R00 = a.R00 * b.R00 + a.R01 * b.R10 + a.R02 * b.R20, R01 = a.R00 * b.R01 + a.R01 * b.R11 + a.R02 * b.R21, R02 = a.R00 * b.R02 + a.R01 * b.R12 + a.R02 * b.R22,
        R10 = a.R10 * b.R00 + a.R11 * b.R10 + a.R12 * b.R20, R11 = a.R10 * b.R01 + a.R11 * b.R11 + a.R12 * b.R21, R12 = a.R10 * b.R02 + a.R11 * b.R12 + a.R12 * b.R22,
        R20 = a.R20 * b.R00 + a.R21 * b.R10 + a.R22 * b.R20, R21 = a.R20 * b.R01 + a.R21 * b.R11 + a.R22 * b.R21, R22 = a.R20 * b.R02 + a.R21 * b.R12 + a.R22 * b.R22,
        Tx = a.R00 * b.Tx + a.R01 * b.Ty + a.R02 * b.Tz + a.Tx,
        Ty = a.R10 * b.Tx + a.R11 * b.Ty + a.R12 * b.Tz + a.Ty,
        Tz = a.R20 * b.Tx + a.R21 * b.Ty + a.R22 * b.Tz + a.Tz,
    };

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vec3 Move(in Motion m, in Vec3 v) => new(
        m.R00 * v.x + m.R01 * v.y + m.R02 * v.z + m.Tx,
        m.R10 * v.x + m.R11 * v.y + m.R12 * v.z + m.Ty,
        m.R20 * v.x + m.R21 * v.y + m.R22 * v.z + m.Tz);

    /// <summary>
    /// The same chain with 3×3 rotation matrices and translations. exp(θ/2 · L) for the dual line of
    /// a ∧ b ∧ ni turns by θ about b − a by the right-hand rule, as Rodrigues' matrix does.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in JointAngles x, out Vec3 p)
    {
        // R1: about the z axis through the origin, written out.
        var (s1, c1) = Math.SinCos(x.A1);
        var m1 = new Motion { R00 = c1, R01 = -s1, R10 = s1, R11 = c1, R22 = 1 };
        // joint 2: the y axis through J1, both turned by R1
        var m2 = AboutLine(J1.x * c1, J1.x * s1, J1.z, -s1, c1, 0, x.A2);
        var m21 = After(m2, m1);
        var j2f = Move(m21, J2);
        // joint 3: the y axis through J2, carried by R2 R1 (its y column)
        var m3 = AboutLine(j2f.x, j2f.y, j2f.z, m21.R01, m21.R11, m21.R21, x.A3);
        // T2: J2 by R2 R1 minus J2 by R1 alone; C = R3 T2 R1
        double dx = j2f.x - J2.x * c1, dy = j2f.y - J2.x * s1, dz = j2f.z - J2.z;
        var c = After(m3, new Motion { R00 = c1, R01 = -s1, R10 = s1, R11 = c1, R22 = 1, Tx = dx, Ty = dy, Tz = dz });
        // joint 4: the x axis through J3 (the unit direction from J3 to Jg), carried by C
        var p4 = Move(c, J3);
        var m4 = AboutLine(p4.x, p4.y, p4.z, c.R00, c.R10, c.R20, x.A4);
        var d = After(m4, c);
        // joint 5: the y axis through J3, carried by R4 C
        var p5 = Move(d, J3);
        var mg = AboutLine(p5.x, p5.y, p5.z, d.R01, d.R11, d.R21, x.A5);
        // the gripper: Jg by Rg C
        var q = Move(c, Jg);
        p = Move(mg, q);
    }
}
