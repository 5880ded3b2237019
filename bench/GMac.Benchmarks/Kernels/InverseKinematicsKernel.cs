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
        var (tmp4, tmp5) = Math.SinCos(tmp3);
        double tmp6 = 0.5 * x.A3;
        var (tmp7, tmp8) = Math.SinCos(tmp6);
        double tmp9 = 0.5 * x.A4;
        var (tmp10, tmp11) = Math.SinCos(tmp9);
        double tmp12 = 0.5 * x.A5;
        var (tmp13, tmp14) = Math.SinCos(tmp12);
        double tmp15 = tmp1 * tmp1;
        double tmp16 = tmp2 * tmp2;
        double tmp17 = tmp15 - tmp16;
        double tmp18 = tmp17 * tmp4;
        double tmp19 = -(tmp1 * tmp2);
        double tmp20 = tmp19 * tmp4;
        double tmp21 = -2.0 * tmp20;
        double tmp22 = -680.0 * tmp18;
        double tmp23 = -1360.0 * tmp20;
        double tmp24 = tmp16 + tmp15;
        double tmp25 = -200.0 * tmp4 * tmp24;
        double tmp26 = tmp2 * tmp5;
        double tmp27 = -(tmp1 * tmp5);
        double tmp28 = tmp1 * tmp21 - tmp2 * tmp18;
        double tmp29 = tmp1 * tmp18 + tmp2 * tmp21;
        double tmp30 = tmp1 * tmp23 + tmp2 * tmp22;
        double tmp31 = tmp2 * tmp25;
        double tmp32 = tmp1 * tmp25;
        double tmp33 = tmp7 * (tmp26 * tmp26 + tmp28 * tmp28 - tmp27 * tmp27 - tmp29 * tmp29);
        double tmp34 = 2.0 * tmp7 * (tmp28 * tmp29 - tmp26 * tmp27);
        double tmp35 = 2.0 * (tmp2 * tmp23 - tmp1 * tmp22);
        double tmp36 = tmp35 - 3140.0 * tmp29;
        double tmp37 = 2.0 * tmp30;
        double tmp38 = tmp28 * tmp31 - (3140.0 * tmp28 + 200.0 * tmp26 - tmp37) * tmp26;
        double tmp39 = tmp29 * tmp32 - (200.0 * tmp27 + tmp36) * tmp27;
        double tmp40 = 200.0 * tmp17 + tmp39 - tmp38;
        double tmp41 = -2.0 * tmp32 - 400.0 * tmp29;
        double tmp42 = tmp41 - 3140.0 * tmp27;
        double tmp43 = -400.0 * tmp27 - tmp36;
        double tmp44 = tmp26 * tmp43 + tmp28 * tmp42 + 2.0 * (tmp27 * tmp30 - tmp29 * tmp31) + 400.0 * tmp19;
        double tmp45 = (tmp37 - 1570.0 * tmp28) * tmp28 + (1570.0 * tmp26 - 400.0 * tmp28 - 2.0 * tmp31) * tmp26;
        double tmp46 = (tmp35 - 1570.0 * tmp29) * tmp29 - tmp27 * (tmp41 - 1570.0 * tmp27);
        double tmp47 = tmp46 - (1570.0 * tmp24 - tmp45);
        double tmp48 = tmp7 * (tmp45 - tmp46) - 0.5 * (tmp33 * tmp47 + tmp8 * tmp40);
        double tmp49 = tmp7 * (tmp26 * tmp42 + 2.0 * (tmp27 * tmp31 + tmp29 * tmp30) - tmp28 * tmp43) - 0.5 * (tmp34 * tmp47 + tmp8 * tmp44);
        double tmp50 = tmp7 * (tmp38 + tmp39) + 0.5 * (tmp33 * tmp40 + tmp34 * tmp44 - tmp8 * tmp47);
        double tmp51 = tmp2 * tmp8;
        double tmp52 = -(tmp1 * tmp8);
        double tmp53 = tmp1 * tmp34 + tmp2 * tmp33;
        double tmp54 = tmp2 * tmp34 - tmp1 * tmp33;
        double tmp55 = tmp1 * tmp49 + tmp2 * tmp48;
        double tmp56 = tmp2 * tmp49 - tmp1 * tmp48;
        double tmp57 = tmp2 * tmp50;
        double tmp58 = -(tmp1 * tmp50);
        double tmp59 = -2.0 * tmp10;
        double tmp60 = (tmp52 * tmp54 - tmp51 * tmp53) * tmp59;
        double tmp61 = (tmp51 * tmp52 + tmp53 * tmp54) * tmp59;
        double tmp62 = tmp10 * (tmp52 * tmp52 + tmp53 * tmp53 - tmp51 * tmp51 - tmp54 * tmp54);
        double tmp63 = 2.0 * tmp56;
        double tmp64 = 3440.0 * tmp54 - tmp63;
        double tmp65 = 2.0 * tmp58;
        double tmp66 = tmp10 * (tmp51 * (tmp65 - 3440.0 * tmp52) + tmp53 * tmp64 + 2.0 * (tmp52 * tmp57 - tmp54 * tmp55));
        double tmp67 = 2.0 * tmp55;
        double tmp68 = tmp10 * (tmp51 * (2.0 * tmp57 - 1720.0 * tmp51) + tmp52 * (1720.0 * tmp52 - tmp65) + tmp53 * (tmp67 - 1720.0 * tmp53) + tmp54 * (1720.0 * tmp54 - tmp63));
        double tmp69 = tmp10 * (tmp51 * tmp64 + tmp52 * (3440.0 * tmp53 - tmp67) - 2.0 * (tmp53 * tmp58 + tmp54 * tmp57));
        double tmp70 = tmp51 * tmp11 - tmp52 * tmp60 - tmp53 * tmp61 - tmp54 * tmp62;
        double tmp71 = tmp51 * tmp60 + tmp52 * tmp11 + tmp53 * tmp62 - tmp54 * tmp61;
        double tmp72 = tmp51 * tmp61 + tmp53 * tmp11 + tmp54 * tmp60 - tmp52 * tmp62;
        double tmp73 = tmp51 * tmp62 + tmp52 * tmp61 + tmp54 * tmp11 - tmp53 * tmp60;
        double tmp74 = tmp51 * tmp66 + tmp55 * tmp11 + tmp56 * tmp60 + tmp57 * tmp61 - tmp52 * tmp68 - tmp53 * tmp69 - tmp58 * tmp62;
        double tmp75 = tmp51 * tmp69 + tmp53 * tmp66 + tmp54 * tmp68 + tmp57 * tmp11 - tmp55 * tmp61 - tmp56 * tmp62 - tmp58 * tmp60;
        double tmp76 = 2.0 * tmp13;
        double tmp77 = (tmp70 * tmp73 + tmp71 * tmp72) * tmp76;
        double tmp78 = tmp13 * (tmp70 * tmp70 + tmp72 * tmp72 - tmp71 * tmp71 - tmp73 * tmp73);
        double tmp79 = (tmp72 * tmp73 - tmp70 * tmp71) * tmp76;
        double tmp80 = 2.0 * (tmp51 * tmp68 + tmp52 * tmp66 + tmp56 * tmp11 + tmp57 * tmp62 + tmp58 * tmp61 - tmp54 * tmp69 - tmp55 * tmp60);
        double tmp81 = 2.0 * (tmp52 * tmp69 + tmp54 * tmp66 + tmp55 * tmp62 + tmp57 * tmp60 + tmp58 * tmp11 - tmp53 * tmp68 - tmp56 * tmp61);
        double tmp82 = 2.0 * tmp74;
        double tmp83 = 2.0 * tmp75;
        double tmp84 = tmp81 - 2160.0 * tmp73;
        double tmp85 = tmp13 * (tmp70 * (1720.0 * tmp70 - 2160.0 * tmp72 - tmp83) + tmp71 * (tmp84 - 1720.0 * tmp71) + tmp72 * (tmp82 - 1720.0 * tmp72) + tmp73 * (1720.0 * tmp73 - tmp80));
        double tmp86 = tmp80 - 3440.0 * tmp73;
        double tmp87 = tmp13 * (tmp70 * (tmp84 - 3440.0 * tmp71) + tmp72 * (2160.0 * tmp71 + tmp86) + 2.0 * (tmp71 * tmp75 + tmp73 * tmp74));
        double tmp88 = tmp13 * (tmp73 * (1080.0 * tmp73 - tmp81) - (tmp71 * (1080.0 * tmp71 + tmp86) - tmp70 * (tmp82 - 1080.0 * tmp70 - 3440.0 * tmp72) - tmp72 * (1080.0 * tmp72 + tmp83)));
        double tmp89 = tmp54 * tmp79 - (tmp51 * tmp14 - tmp52 * tmp77 - tmp53 * tmp78);
        double tmp90 = tmp51 * tmp77 + tmp52 * tmp14 + tmp53 * tmp79 - tmp54 * tmp78;
        double tmp91 = tmp51 * tmp78 + tmp53 * tmp14 + tmp54 * tmp77 - tmp52 * tmp79;
        double tmp92 = tmp51 * tmp79 + tmp52 * tmp78 + tmp54 * tmp14 - tmp53 * tmp77;
        double tmp93 = tmp51 * tmp85 + tmp55 * tmp14 + tmp56 * tmp77 + tmp57 * tmp78 - tmp52 * tmp87 - tmp53 * tmp88 - tmp58 * tmp79;
        double tmp94 = tmp51 * tmp88 + tmp53 * tmp85 + tmp54 * tmp87 + tmp57 * tmp14 - tmp55 * tmp78 - tmp56 * tmp79 - tmp58 * tmp77;
        double tmp95 = 2.0 * (tmp52 * tmp88 + tmp54 * tmp85 + tmp55 * tmp79 + tmp57 * tmp77 + tmp58 * tmp14 - tmp53 * tmp87 - tmp56 * tmp78);
        double tmp96 = 2.0 * (tmp51 * tmp87 + tmp52 * tmp85 + tmp56 * tmp14 + tmp57 * tmp79 + tmp58 * tmp78 - tmp54 * tmp88 - tmp55 * tmp77);
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
