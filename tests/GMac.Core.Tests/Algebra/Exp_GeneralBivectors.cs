using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// exp of bivectors that are no blades (two commuting planes: 4D rotations, PGA screw motions,
/// conformal and spacetime bivectors with a 4-vector square) against the power series summed in
/// exact rationals, numerically and as the symbolic formula code generation emits.
/// </summary>
public class Exp_GeneralBivectors
{
    private static readonly Frame E4 = Frame.Euclidean("e4d", 4);
    private static readonly Frame E5 = Frame.Euclidean("e5d", 5);

    private static Frame ByName(string name) => name switch
    {
        "e4d" => E4,
        "e5d" => E5,
        _ => TestFrames.ByName(name),
    };

    /// <summary>A bivector with random rational coefficients p/q, |p| ≤ 6, q ≤ 4 (seeded).</summary>
    private static Multivector<Scalar> RandomBivector(Frame frame, int seed)
    {
        var random = new Random(seed);
        var b = Multivector<Scalar>.Zero(frame);
        for (var id = 0; id < frame.BladeCount; id++)
            if (System.Numerics.BitOperations.PopCount((uint)id) == 2)
                b += Multivector<Scalar>.Basis(frame, new BasisBlade(id)) * Scalar.Constant(new Rational(random.Next(-6, 7), random.Next(1, 5)));
        return b;
    }

    private static double ToDouble(Scalar c) => c.TryGetConstant(out var v) ? v.ToDouble() : throw new InvalidOperationException($"{c}");

    public static IEnumerable<object[]> Cases() =>
        from frame in new[] { "e4d", "e5d", "pga", "cga5d", "sta", "cl41" }
        from seed in new[] { 1, 2, 3 }
        select new object[] { frame, seed };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Exp_of_a_random_bivector_is_its_rational_power_series(string frameName, int seed)
    {
        var frame = ByName(frameName);
        var exact = RandomBivector(frame, seed);
        var numeric = exact.Convert(ToDouble);
        Assert.True(numeric.Gp(numeric).Grade(4).TermCount > 0, "the case must not be a blade");
        var series = Exp_NearZeroAndSigns.RationalSeries(exact);
        MultivectorAssert.Close(series, numeric.Exp(), 1e-12);
        var symbolic = SymbolicMultivector.Variables(frame, "b", numeric.Terms.Select(t => t.Blade));
        var values = numeric.Terms.ToDictionary(t => SymbolicMultivector.VariableName(frame, "b", t.Blade), t => t.Coefficient);
        MultivectorAssert.Close(series, symbolic.Exp().Evaluate(values), 1e-12);
    }

    public static IEnumerable<object[]> Scales() =>
        from scale in new[] { 0.0, 1e-200, 1e-8, 0.6, 1e3 }
        from ratio in new[] { 1.0, 0.37, 1e-9 }
        select new object[] { scale, ratio };

    /// <summary>
    /// θ₁ e1^e2 + θ₂ e3^e4 in a rotated basis (B and the closed form (cos θ₁ + e12 sin θ₁)(cos θ₂ + e34 sin θ₂)
    /// sandwiched by one fixed rotor): equal angles (isoclinic), unequal, and one plane almost empty.
    /// </summary>
    [Theory]
    [MemberData(nameof(Scales))]
    public void Exp_of_a_4d_bivector_is_finite_and_accurate_at_every_scale(double scale, double ratio)
    {
        var f = E4;
        Multivector<double> Blade(string name, double c) => Multivector<double>.Basis(f, name) * c;
        var (t1, t2) = (scale, scale * ratio);
        var turn = (Blade("e1^e3", 0.3) + Blade("e2^e4", -0.8) + Blade("e1^e4", 0.5)).Exp();
        var b = turn.Apply(Blade("e1^e2", t1) + Blade("e3^e4", t2)).Grade(2);
        var closed = (Multivector<double>.FromScalar(f, Math.Cos(t1)) + Blade("e1^e2", Math.Sin(t1)))
            .Gp(Multivector<double>.FromScalar(f, Math.Cos(t2)) + Blade("e3^e4", Math.Sin(t2)));
        var expected = turn.Apply(closed);
        var symbolic = SymbolicMultivector.Variables(f, "b", b.Terms.Select(t => t.Blade));
        var values = b.Terms.ToDictionary(t => SymbolicMultivector.VariableName(f, "b", t.Blade), t => t.Coefficient);
        // Absolute: the inputs θ·n are rounded, so large angles are known to a few ulp(θ) only; and the
        // eigenvalue s + w = −(θ₁ − θ₂)² is a difference of numbers of size θ², absolutely within ε·θ².
        var tolerance = Math.Max(1e-14 * Math.Max(1, scale), 1e-16 * scale * scale);
        foreach (var actual in new[] { b.Exp(), symbolic.Exp().Evaluate(values) })
        {
            Assert.All(actual.Terms, t => Assert.True(double.IsFinite(t.Coefficient)));
            MultivectorAssert.Close(expected, actual, tolerance);
            // Small angles: the bivector part is B itself to first order, relatively.
            if (scale is > 0 and < 1e-7)
                foreach (var (blade, c) in b.Terms) Assert.Equal(c, actual[blade], Math.Abs(c) * 1e-12);
        }
    }
}
