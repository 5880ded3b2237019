using System.Runtime.CompilerServices;
using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;
using static GMac.Benchmarks.Kernels.DirectAlgebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>(7.10)-(7.12) rotor interpolation R = exp(α log(R2 R1⁻¹)) R1.</summary>
public sealed class RotorInterpolateKernel : GaKernel<RotorPair, Rotor3>
{
    public override string MacroName => "RotorInterpolate";
    public override string Source => "thesis (7.10)-(7.12)";

    /// <summary>
    /// Counted by hand, as spherical linear interpolation: R1·R2 (4 mul, 3 add), acos, sin Ω, 1/sin Ω (1 div),
    /// (1 − α)Ω and αΩ (2 mul, 1 add), two sines, the two weights (2 mul), the weighted sum (8 mul, 4 add).
    /// </summary>
    public override OperationCount HandOperations => new(Additions: 8, Multiplications: 16, Divisions: 1, Calls: 4);

    /// <summary>
    /// Unit rotors whose relative rotor R2 R1⁻¹ is not too close to ±1, where acos loses precision. Its
    /// scalar part takes either sign: the macro's principal logarithm and slerp both go the way R1·R2 points.
    /// </summary>
    protected override RotorPair CreateInput(Random random)
    {
        while (true)
        {
            var r1 = UnitRotor(random);
            var r2 = UnitRotor(random);
            var dot = r1.w * r2.w + r1.x * r2.x + r1.y * r2.y + r1.z * r2.z;
            if (Math.Abs(dot) < 0.995) return new RotorPair { R1 = r1, R2 = r2, Alpha = random.NextDouble() };
        }
    }

    private static Rotor3 UnitRotor(Random random)
    {
        double w, x, y, z, n;
        do
        {
            (w, x, y, z) = (Signed(random), Signed(random), Signed(random), Signed(random));
            n = Math.Sqrt(w * w + x * x + y * y + z * z);
        } while (n < 0.1 || n > 1);
        return new Rotor3(w / n, x / n, y / n, z / n);
    }

    protected override double[] Components(Rotor3 r) => [r.w, r.x, r.y, r.z];

    protected override void RunGenerated(RotorPair[] inputs, Rotor3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Generated(in inputs[i], out outputs[i]);
    }

    protected override void RunDirect(RotorPair[] inputs, Rotor3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) outputs[i] = Direct(in inputs[i]);
    }

    protected override void RunHand(RotorPair[] inputs, Rotor3[] outputs)
    {
        for (var i = 0; i < inputs.Length; i++) Hand(in inputs[i], out outputs[i]);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Generated(in RotorPair p, out Rotor3 r)
    {
        #region GMac : RotorInterpolate
        //GMac.Bind("r1.1", "<p.R1.w>");
        //GMac.Bind("r1.e2^e3", "<p.R1.x>");
        //GMac.Bind("r1.e3^e1", "<p.R1.y>");
        //GMac.Bind("r1.e1^e2", "<p.R1.z>");
        //GMac.Bind("r2.1", "<p.R2.w>");
        //GMac.Bind("r2.e2^e3", "<p.R2.x>");
        //GMac.Bind("r2.e3^e1", "<p.R2.y>");
        //GMac.Bind("r2.e1^e2", "<p.R2.z>");
        //GMac.Bind("alpha.1", "<p.Alpha>");
        //GMac.Bind("r.1", "<r.w>");
        //GMac.Bind("r.e2^e3", "<r.x>");
        //GMac.Bind("r.e3^e1", "<r.y>");
        //GMac.Bind("r.e1^e2", "<r.z>");
        double tmp0 = p.R1.w * p.R2.w + p.R1.x * p.R2.x + p.R1.y * p.R2.y + p.R1.z * p.R2.z;
        double tmp1 = Math.Acos(tmp0);
        double tmp2 = Math.Sin(tmp1);
        double tmp3 = tmp1 * p.Alpha;
        var (tmp4, tmp5) = Math.SinCos(tmp3);
        double tmp6 = tmp4 / tmp2;
        double tmp7 = tmp5 - tmp0 * tmp6;
        double tmp8 = p.R1.w * tmp7 + p.R2.w * tmp6;
        double tmp9 = p.R1.x * tmp7 + p.R2.x * tmp6;
        double tmp10 = p.R1.y * tmp7 + p.R2.y * tmp6;
        r.z = p.R1.z * tmp7 + p.R2.z * tmp6;
        r.w = tmp8;
        r.x = tmp9;
        r.y = tmp10;
        #endregion
    }

    public static Rotor3 Direct(in RotorPair p)
    {
        var r1 = Of(p.R1);
        var r2 = Of(p.R2);
        return ToRotor(RotorExp(p.Alpha * RotorLog(r2.Gp(r1.Inverse()))).Gp(r1));
    }

    /// <summary>(7.10) e^B = cos φ + sin(φ)/φ B, φ = √(−B²).</summary>
    private static Multivector<double> RotorExp(Multivector<double> b)
    {
        var phi = Math.Sqrt(-b.Sp(b).ScalarPart);
        return Scalar3(Math.Cos(phi)) + Math.Sin(phi) / phi * b;
    }

    /// <summary>(7.11) log R = R₂/‖R₂‖ atan2(‖R₂‖, ⟨R⟩₀), the principal logarithm, as the library macro takes it.</summary>
    private static Multivector<double> RotorLog(Multivector<double> r)
    {
        var r2 = r.Grade(2);
        var n2 = r2.Norm();
        return r2 / n2 * Math.Atan2(n2, r.ScalarPart);
    }

    /// <summary>Slerp: (R2 R1⁻¹)^α R1 = [sin((1 − α)Ω) R1 + sin(αΩ) R2] / sin Ω with cos Ω = R1·R2.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Hand(in RotorPair p, out Rotor3 r)
    {
        ref readonly var a = ref p.R1;
        ref readonly var b = ref p.R2;
        var omega = Math.Acos(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z);
        var inverseSin = 1 / Math.Sin(omega);
        var s1 = Math.Sin((1 - p.Alpha) * omega) * inverseSin;
        var s2 = Math.Sin(p.Alpha * omega) * inverseSin;
        r.w = s1 * a.w + s2 * b.w;
        r.x = s1 * a.x + s2 * b.x;
        r.y = s1 * a.y + s2 * b.y;
        r.z = s1 * a.z + s2 * b.z;
    }
}
