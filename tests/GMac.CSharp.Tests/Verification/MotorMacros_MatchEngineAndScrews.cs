using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// The generated code of the motor macros (dsl/macros/motors.gmac): against the numeric engine on
/// random inputs, and against motors built from closed-form factors, cos(φ/2) − sin(φ/2)·plane and
/// 1 + ½e0∧v (1 − ½v∧ni in CGA), for a screw by φ about an axis through c with translation d along
/// it: exp of the screw bivector is that motor, log returns the bivector, sqrt the half screw and
/// interpolation the fraction t of it; at 0, 1e-200, 1e-8 and large angles, finite.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class MotorMacros_MatchEngineAndScrews
{
    private static readonly Frame Pga = new("pga3d", ["e0", "e1", "e2", "e3"], Metric.FromMatrix(new Rational[,]
    {
        { 0, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 },
    }));

    private static readonly Frame Cga = Frame.Conformal3D();
    private static readonly double[] Axis = [2.0 / 3, -1.0 / 3, 2.0 / 3];
    private static readonly double[] Center = [0.5, -1.0, 2.0];

    // Generated and compiled once per macro for all cases.
    private static readonly Dictionary<string, MacroKernel> Kernels = [];

    private static MacroKernel Kernel(string macro)
    {
        lock (Kernels)
        {
            if (!Kernels.TryGetValue(macro, out var kernel)) Kernels[macro] = kernel = MacroKernel.Create(macro, "double");
            return kernel;
        }
    }

    [Theory]
    [InlineData("PgaMotorExp")]
    [InlineData("PgaMotorLog")]
    [InlineData("PgaMotorSqrt")]
    [InlineData("PgaMotorInterpolate")]
    [InlineData("CgaMotorExp")]
    [InlineData("CgaMotorLog")]
    [InlineData("RotorSlerp")]
    public void Generated_code_matches_the_numeric_engine_on_random_inputs(string macro)
    {
        var kernel = Kernel(macro);
        var normalized = kernel.Plan.Macro.Inputs.Where(i => i.Class is { IsNormalized: true })
            .Select(i => (IReadOnlyList<string>)kernel.Plan.InputTexts.Where(x => x.Value.StartsWith(i.Name + "_", StringComparison.Ordinal)).Select(x => x.Key).ToList())
            .ToList();
        var result = RegionVerifier.Verify(kernel.Kernel, kernel.Plan, [], normalized, RegionVerifier.Tolerance, seed: 11, samples: 25);
        Assert.True(result.Passed, result.Failure);
        Assert.True(result.Samples >= 20, $"only {result.Samples} samples");
    }

    private static Multivector<double> B(Frame f, string blade, double c) => Multivector<double>.Basis(f, blade) * c;

    private static Multivector<double> Plane(Frame f, double[] a) => B(f, "e2^e3", a[0]) + B(f, "e3^e1", a[1]) + B(f, "e1^e2", a[2]);

    /// <summary>The translation generator: ½e0∧v in PGA, −½v∧ni in CGA.</summary>
    private static Multivector<double> Shift(Frame f, double[] v) => f == Pga
        ? (B(f, "e0^e1", v[0]) + B(f, "e0^e2", v[1]) + B(f, "e0^e3", v[2])) * 0.5
        : (B(f, "e1^ni", v[0]) + B(f, "e2^ni", v[1]) + B(f, "e3^ni", v[2])) * -0.5;

    private static Multivector<double> One(Frame f) => Multivector<double>.FromScalar(f, 1);

    /// <summary>Screw motor and bivector: rotation by φ about the axis through c, translation d along the axis.</summary>
    private static (Multivector<double> Motor, Multivector<double> Bivector) Screw(Frame f, double angle, double d)
    {
        var tc = One(f) + Shift(f, Center);
        var rotor = One(f) * Math.Cos(angle / 2) - Plane(f, Axis) * Math.Sin(angle / 2);
        var along = One(f) + Shift(f, Axis.Select(x => x * d).ToArray());
        var motor = tc.Gp(rotor).Gp(along).Gp(tc.Reverse());
        var bivector = tc.Gp(Plane(f, Axis) * (-angle / 2) + Shift(f, Axis.Select(x => x * d).ToArray())).Gp(tc.Reverse()).Grade(2);
        return (motor, bivector);
    }

    private static Dictionary<string, double> Inputs(string name, Multivector<double> m, Dictionary<string, double>? into = null)
    {
        into ??= new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var (blade, c) in m.Terms) into[Key(name, m.Frame, blade)] = c;
        return into;
    }

    private static string Key(string name, Frame f, BasisBlade blade) => blade.Id == 0 ? $"{name}_s" : $"{name}_{f.BladeName(blade).Replace("^", "_", StringComparison.Ordinal)}";

    private static void Matches(Multivector<double> expected, string name, Dictionary<string, double> outputs, double tolerance)
    {
        foreach (var (key, value) in outputs)
            Assert.True(double.IsFinite(value), $"{key} is {value}");
        for (var id = 0; id < expected.Frame.BladeCount; id++)
        {
            var blade = new BasisBlade(id);
            var e = expected[blade];
            var a = outputs.TryGetValue(Key(name, expected.Frame, blade), out var v) ? v : 0.0;
            Assert.True(Math.Abs(e - a) <= tolerance, $"{expected.Frame.BladeName(blade)}: {a} instead of {e}");
        }
    }

    public static IEnumerable<object[]> Screws() =>
        from angle in new[] { 0.0, 1e-200, 1e-8, 0.7, 3.0, 6.0 }
        from d in new[] { 0.0, 1e-9, 1.3 }
        select new object[] { angle, d };

    [Theory]
    [MemberData(nameof(Screws))]
    public void Generated_pga_exp_log_and_sqrt_follow_the_screw(double angle, double d)
    {
        var (motor, bivector) = Screw(Pga, angle, d);
        Matches(motor, "m", Kernel("PgaMotorExp").Run(Inputs("b", bivector)), 1e-13);
        Matches(bivector, "b", Kernel("PgaMotorLog").Run(Inputs("m", motor)), 1e-13);
        Matches(Screw(Pga, angle / 2, d / 2).Motor, "r", Kernel("PgaMotorSqrt").Run(Inputs("m", motor)), 1e-13);
    }

    [Theory]
    [InlineData(1e3, 0.5)]
    [InlineData(-40.0, 7.0)]
    public void Generated_pga_exp_is_accurate_at_large_angles(double angle, double d)
    {
        var (motor, bivector) = Screw(Pga, angle, d);
        // The inputs carry rounding of size ulp(angle·d): the motor is known only that well.
        Matches(motor, "m", Kernel("PgaMotorExp").Run(Inputs("b", bivector)), 1e-15 * Math.Abs(angle) * (1 + d) * 8);
    }

    [Theory]
    [MemberData(nameof(Screws))]
    public void Generated_cga_exp_and_log_follow_the_screw(double angle, double d)
    {
        var (motor, bivector) = Screw(Cga, angle, d);
        Matches(motor, "m", Kernel("CgaMotorExp").Run(Inputs("b", bivector)), 1e-13);
        Matches(bivector, "b", Kernel("CgaMotorLog").Run(Inputs("m", motor)), 1e-13);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(0.25)]
    [InlineData(0.5)]
    [InlineData(1.0)]
    public void Generated_motor_interpolation_moves_a_fraction_of_the_screw(double t)
    {
        // From a start motor A to A·M(φ, d): at t, A·M(tφ, td).
        var start = Screw(Pga, -1.1, 0.4).Motor.Gp(One(Pga) + Shift(Pga, [0.3, 0.2, -0.9]));
        var inputs = Inputs("m0", start, Inputs("m1", start.Gp(Screw(Pga, 2.5, 1.7).Motor)));
        inputs["t_s"] = t;
        Matches(start.Gp(Screw(Pga, 2.5 * t, 1.7 * t).Motor), "m", Kernel("PgaMotorInterpolate").Run(inputs), 1e-12);
    }
}
