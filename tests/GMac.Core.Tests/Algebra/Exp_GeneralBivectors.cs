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
}
