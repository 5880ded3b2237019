using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// log and sqrt of rotors and PGA motors against axis, angle and pitch: rotors and motors are
/// built as products of closed-form factors (cos + sin·plane, 1 + ½e0∧v), their logs compared with
/// the screw bivector, their action with the Rodrigues formula, and sqrt(M)² with M; numerically
/// and as the symbolic formulas code generation emits.
/// </summary>
public class Log_RotorsAndMotors
{
    private static readonly Frame E3 = TestFrames.E3;
    private static readonly Frame E4 = Frame.Euclidean("e4d", 4);
    private static readonly Frame Pga = new("pga3d", ["e0", "e1", "e2", "e3"], Metric.FromMatrix(new Rational[,]
    {
        { 0, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 },
    }));

    private static readonly double[] Axis = [2.0 / 3, -1.0 / 3, 2.0 / 3];
    private static readonly double[] Center = [0.5, -1.0, 2.0];

    private static Multivector<double> B(Frame f, string blade, double c) => Multivector<double>.Basis(f, blade) * c;

    /// <summary>The plane of rotation about axis a (its Euclidean dual): a₁e23 + a₂e31 + a₃e12.</summary>
    private static Multivector<double> Plane(Frame f, double[] a) => B(f, "e2^e3", a[0]) + B(f, "e3^e1", a[1]) + B(f, "e1^e2", a[2]);

    private static Multivector<double> Rotor(Frame f, double[] a, double angle) =>
        Multivector<double>.FromScalar(f, Math.Cos(angle / 2)) - Plane(f, a) * Math.Sin(angle / 2);

    /// <summary>1 + ½ e0∧v: translation by v.</summary>
    private static Multivector<double> Translator(double[] v) =>
        Multivector<double>.FromScalar(Pga, 1) + (B(Pga, "e0^e1", v[0]) + B(Pga, "e0^e2", v[1]) + B(Pga, "e0^e3", v[2])) * 0.5;

    private static double[] Scaled(double[] v, double s) => v.Select(x => x * s).ToArray();

    /// <summary>The point x e023 + y e031 + z e012 + e123, moved by +v under 1 + ½e0∧v.</summary>
    private static Multivector<double> Point(double[] x) =>
        B(Pga, "e0^e2^e3", x[0]) + B(Pga, "e0^e3^e1", x[1]) + B(Pga, "e0^e1^e2", x[2]) + B(Pga, "e1^e2^e3", 1);

    private static double[] Coordinates(Multivector<double> p)
    {
        var w = p["e1^e2^e3"];
        return [p["e0^e2^e3"] / w, p["e0^e3^e1"] / w, p["e0^e1^e2"] / w];
    }

    /// <summary>Rodrigues: rotation of x by φ about the unit axis a through the origin.</summary>
    private static double[] Rotate(double[] x, double[] a, double angle)
    {
        var dot = a.Zip(x, (p, q) => p * q).Sum();
        double[] cross = [a[1] * x[2] - a[2] * x[1], a[2] * x[0] - a[0] * x[2], a[0] * x[1] - a[1] * x[0]];
        return Enumerable.Range(0, 3).Select(i => x[i] * Math.Cos(angle) + cross[i] * Math.Sin(angle) + a[i] * dot * (1 - Math.Cos(angle))).ToArray();
    }

    private static Multivector<double> SymbolicLog(Multivector<double> m)
    {
        var symbolic = SymbolicMultivector.Variables(m.Frame, "m", m.Terms.Select(t => t.Blade));
        var values = m.Terms.ToDictionary(t => SymbolicMultivector.VariableName(m.Frame, "m", t.Blade), t => t.Coefficient);
        return symbolic.Log().Evaluate(values);
    }

    private static void Finite(Multivector<double> m) =>
        Assert.All(m.Terms, t => Assert.True(double.IsFinite(t.Coefficient), $"{m.Frame.BladeName(t.Blade)} is {t.Coefficient}"));

    [Theory]
    [InlineData(0.0)]
    [InlineData(1e-200)]
    [InlineData(1e-8)]
    [InlineData(0.7)]
    [InlineData(3.0)]
    [InlineData(6.0)]
    public void Log_of_a_3d_rotor_is_minus_half_the_angle_times_the_rotation_plane(double angle)
    {
        var r = Rotor(E3, Axis, angle);
        var expected = Plane(E3, Axis) * (-angle / 2);
        foreach (var log in new[] { r.Log(), SymbolicLog(r) })
        {
            Finite(log);
            MultivectorAssert.Close(expected, log, 1e-14);
            double[] x = [0.3, -1.1, 0.8];
            var moved = log.Exp().Apply(Multivector<double>.Vector(E3, x));
            var rodrigues = Rotate(x, Axis, angle);
            for (var i = 0; i < 3; i++) MultivectorAssert.Close(rodrigues[i], moved[$"e{i + 1}"], 1e-13);
        }
    }

    public static IEnumerable<object[]> Screws() =>
        from angle in new[] { 0.0, 1e-200, 1e-8, 0.7, 3.0, 6.0 }
        from pitch in new[] { 0.0, 1e-9, 1.3 }
        select new object[] { angle, pitch };

    [Theory]
    [MemberData(nameof(Screws))]
    public void Log_of_a_pga_motor_is_its_screw_bivector(double angle, double translation)
    {
        // Rotation by φ about the axis through c along a, then translation by d along a.
        var tc = Translator(Center);
        var motor = tc.Gp(Translator(Scaled(Axis, translation))).Gp(Rotor(Pga, Axis, angle)).Gp(Translator(Scaled(Center, -1)));
        var screw = Plane(Pga, Axis) * (-angle / 2) + (B(Pga, "e0^e1", Axis[0]) + B(Pga, "e0^e2", Axis[1]) + B(Pga, "e0^e3", Axis[2])) * (translation / 2);
        var expected = tc.Gp(screw).Gp(tc.Reverse());
        foreach (var log in new[] { motor.Log(), SymbolicLog(motor) })
        {
            Finite(log);
            MultivectorAssert.Close(expected, log, 1e-13);
            double[] x = [0.7, -0.2, 1.1];
            var moved = Coordinates(log.Exp().Apply(Point(x)));
            var truth = Rotate(Enumerable.Range(0, 3).Select(i => x[i] - Center[i]).ToArray(), Axis, angle)
                .Select((v, i) => v + Center[i] + translation * Axis[i]).ToArray();
            for (var i = 0; i < 3; i++) MultivectorAssert.Close(truth[i], moved[i], 1e-12);
        }
        var root = motor.VersorSqrt();
        MultivectorAssert.Close(motor, root.Gp(root), 1e-13);
        MultivectorAssert.Close(expected * 0.5, root.Log(), 1e-13);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void Log_and_sqrt_of_a_4d_rotor_in_two_planes_invert_exp(int seed)
    {
        // Angles below π/2 in each plane: exp(B) is then in log's domain and log returns B.
        var random = new Random(seed);
        var b = Multivector<double>.Zero(E4);
        for (var id = 0; id < E4.BladeCount; id++)
            if (System.Numerics.BitOperations.PopCount((uint)id) == 2)
                b += Multivector<double>.Basis(E4, new BasisBlade(id)) * (random.NextDouble() - 0.5);
        var r = b.Exp();
        MultivectorAssert.Close(b, r.Log(), 1e-13);
        MultivectorAssert.Close(b, SymbolicLog(r), 1e-13);
        var root = r.VersorSqrt();
        MultivectorAssert.Close((b * 0.5).Exp(), root, 1e-13);
    }

    [Fact]
    public void Log_of_an_isoclinic_4d_rotor_is_finite_and_inverts_exp()
    {
        // Equal angles in e1^e2 and e3^e4: the two eigenvalues of B² coincide.
        var b = B(E4, "e1^e2", 0.4) + B(E4, "e3^e4", 0.4);
        var r = (Multivector<double>.FromScalar(E4, Math.Cos(0.4)) + B(E4, "e1^e2", Math.Sin(0.4))).Gp(
            Multivector<double>.FromScalar(E4, Math.Cos(0.4)) + B(E4, "e3^e4", Math.Sin(0.4)));
        Finite(b.Exp());
        MultivectorAssert.Close(r, b.Exp(), 1e-14);
        MultivectorAssert.Close(b, r.Log(), 1e-13);
        MultivectorAssert.Close(b, SymbolicLog(r), 1e-13);
    }
}
