using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// exp of 2-blades against the power series Σ Bᵏ/k! summed in exact rationals until the terms are
/// below 1e-40; finite and accurate at 0, where the squares underflow, near 0 and for large angles,
/// numerically and as the symbolic formula that code generation emits.
/// </summary>
public class Exp_NearZeroAndSigns
{
    /// <summary>Σ Bᵏ/k! in rationals (symbolic constants), to convergence.</summary>
    internal static Multivector<double> RationalSeries(Multivector<Scalar> b)
    {
        var sum = Multivector<Scalar>.FromScalar(b.Frame, Scalar.One);
        var term = sum;
        var small = new Rational(1, System.Numerics.BigInteger.Pow(10, 40));
        for (var k = 1; k < 400; k++)
        {
            term = term.Gp(b) * Scalar.Constant(new Rational(1, k));
            sum += term;
            if (term.Terms.All(t => t.Coefficient.TryGetConstant(out var c) && c.Abs().CompareTo(small) < 0)) break;
        }
        return sum.Convert(ToDouble);
    }

    private static Multivector<Scalar> Exact(Frame frame, params (string Blade, int Numerator, int Denominator)[] terms) =>
        terms.Aggregate(Multivector<Scalar>.Zero(frame),
            (sum, t) => sum + Multivector<Scalar>.Basis(frame, t.Blade) * Scalar.Constant(new Rational(t.Numerator, t.Denominator)));

    private static double ToDouble(Scalar c) => c.TryGetConstant(out var v) ? v.ToDouble() : throw new InvalidOperationException($"{c} is not a constant");

    public static IEnumerable<object[]> RationalBlades() =>
    [
        ["e3d", new[] { ("e1^e2", 3, 7), ("e1^e3", -5, 4), ("e2^e3", 1, 3) }],          // rotation, θ² = −β > 0
        ["e3d", new[] { ("e1^e2", 31, 2) }],                                           // θ = 15.5
        ["cl41", new[] { ("e1^e5", 4, 5) }],                                            // boost, β = +16/25
        ["sta", new[] { ("e1^e2", 7, 3) }],                                             // Cl(1,3): e1 timelike, a boost
        ["sta", new[] { ("e2^e3", -2, 9) }],                                            // spatial rotation
        ["pga", new[] { ("e1^e4", 5, 2), ("e2^e4", -1, 3) }],                           // PGA translator: B² = 0
        ["pga", new[] { ("e1^e2", 2, 3), ("e1^e4", 1, 5), ("e2^e4", 3, 2) }],            // PGA rotor about a shifted axis
    ];

    [Theory]
    [MemberData(nameof(RationalBlades))]
    public void Exp_of_a_rational_2_blade_is_its_rational_power_series(string frameName, (string, int, int)[] terms)
    {
        var frame = TestFrames.ByName(frameName);
        var exact = Exact(frame, terms);
        var numeric = exact.Convert(ToDouble);
        MultivectorAssert.Close(RationalSeries(exact), numeric.Exp(), 1e-13);
        // The symbolic formula (what generated code computes) for the same blade.
        var symbolic = Symbolic(frame, numeric, out var values);
        MultivectorAssert.Close(RationalSeries(exact), symbolic.Exp().Evaluate(values), 1e-13);
    }

    private static Multivector<Scalar> Symbolic(Frame frame, Multivector<double> b, out Dictionary<string, double> values)
    {
        var symbolic = SymbolicMultivector.Variables(frame, "b", b.Terms.Select(t => t.Blade));
        values = b.Terms.ToDictionary(t => SymbolicMultivector.VariableName(frame, "b", t.Blade), t => t.Coefficient);
        return symbolic;
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(1e-200)]
    [InlineData(1e-160)]
    [InlineData(1e-8)]
    [InlineData(0.3)]
    [InlineData(1e3)]
    [InlineData(1e7)]
    public void Exp_of_a_rotation_blade_is_finite_and_accurate_at_every_scale(double scale)
    {
        var f = TestFrames.E3;
        // A unit direction (2/3, −1/3, 2/3), so θ = scale exactly up to rounding of the products.
        var b = (Multivector<double>.Basis(f, "e1^e2") * (2.0 / 3) - Multivector<double>.Basis(f, "e1^e3") * (1.0 / 3)
                 + Multivector<double>.Basis(f, "e2^e3") * (2.0 / 3)) * scale;
        var expected = Multivector<double>.FromScalar(f, Math.Cos(scale)) + b * (scale == 0 ? 1 : Math.Sin(scale) / scale);
        var tolerance = scale > 1 ? 1e-15 * scale : 1e-15;
        AssertFiniteAndClose(expected, b.Exp(), tolerance);
        var symbolic = Symbolic(f, b, out var values);
        AssertFiniteAndClose(expected, symbolic.Exp().Evaluate(values), tolerance);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(1e-200)]
    [InlineData(1e-8)]
    [InlineData(2.5)]
    public void Exp_of_a_boost_blade_is_finite_and_accurate_at_every_scale(double rapidity)
    {
        var f = TestFrames.Cl41;
        // (0.6 e1^e5 + 0.8 e2^e5)² = 0.36 + 0.64 = 1: the symbolic square a² + b² is not a square, so
        // the code divides by √(a² + b²) and must use the guarded calls.
        var plane = Multivector<double>.Basis(f, "e1^e5") * 0.6 + Multivector<double>.Basis(f, "e2^e5") * 0.8;
        var b = plane * rapidity;
        var expected = Multivector<double>.FromScalar(f, Math.Cosh(rapidity)) + plane * Math.Sinh(rapidity);
        AssertFiniteAndClose(expected, b.Exp(), 1e-15);
        var symbolic = Symbolic(f, b, out var values);
        AssertFiniteAndClose(expected, symbolic.Exp().Evaluate(values), 1e-15);
    }

    [Fact]
    public void Exp_of_a_symbolic_scalar_times_a_boost_plane_is_hyperbolic()
    {
        // (no∧ni)² = 1 in the conformal frame: the square s² is ≥ 0 by structure. No division by s
        // remains (s·sinh|s|/|s| = sinh s), so the form stays in exponentials, which combine across
        // versor products; near 0 it is accurate absolutely (e^s − e^−s cancels), not relatively.
        var f = TestFrames.Conformal;
        var s = Scalar.Variable("s");
        var plane = Multivector<Scalar>.Basis(f, "no^ni");
        var exp = (plane * s).Exp();
        foreach (var value in new[] { 0.0, 1e-200, 0.4, -1.7 })
        {
            var values = new Dictionary<string, double> { ["s"] = value };
            var expected = Multivector<double>.FromScalar(f, Math.Cosh(value)) + Multivector<double>.Basis(f, "no^ni") * Math.Sinh(value);
            MultivectorAssert.Close(expected, exp.Evaluate(values), 1e-15);
            Assert.All(exp.Evaluate(values).Terms, t => Assert.True(double.IsFinite(t.Coefficient)));
        }
    }

    [Fact]
    public void Exp_of_a_2_blade_of_unknown_sign_chooses_at_run_time()
    {
        // a e1^e2 + b e1^e5 in Cl(4,1) squares to b² − a²: cos/sin, 1 + B or cosh/sinh by the values.
        var f = TestFrames.Cl41;
        var b = Multivector<Scalar>.Basis(f, "e1^e2") * Scalar.Variable("a") + Multivector<Scalar>.Basis(f, "e1^e5") * Scalar.Variable("b");
        var exp = b.Exp();
        foreach (var (x, y) in new[] { (0.0, 0.0), (0.7, 0.2), (0.2, 0.7), (0.5, 0.5), (1e-200, 0.0), (0.0, 3.0) })
        {
            var numeric = Multivector<double>.Basis(f, "e1^e2") * x + Multivector<double>.Basis(f, "e1^e5") * y;
            var expected = numeric.Exp();
            AssertFiniteAndClose(expected, exp.Evaluate(new Dictionary<string, double> { ["a"] = x, ["b"] = y }), 1e-13);
        }
    }

    private static void AssertFiniteAndClose(Multivector<double> expected, Multivector<double> actual, double tolerance)
    {
        foreach (var (blade, c) in actual.Terms)
            Assert.True(double.IsFinite(c), $"coefficient of {actual.Frame.BladeName(blade)} is {c}");
        for (var id = 0; id < expected.Frame.BladeCount; id++)
        {
            var blade = new BasisBlade(id);
            var (e, a) = (expected[blade], actual[blade]);
            // Relative per coefficient: 1e-200·sin θ/θ must come out as 1e-200, not as 0.
            Assert.True(Math.Abs(e - a) <= tolerance * Math.Max(Math.Abs(e), e == 0 ? 1 : 0),
                $"coefficient of {expected.Frame.BladeName(blade)}: expected {e}, got {a}");
        }
    }
}
