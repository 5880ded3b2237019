using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.Symbolic;
using static GMac.Core.Tests.CodeGeneration.Kernels;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// √P with P + u² = 1 under unit constraints, next to |u|: the block names u once and reads
/// √(1 − u²). Counts are exact on small cases; values are checked on random unit inputs.
/// </summary>
public class NormComplement_Rewrite
{
    private static Scalar V(string name) => Scalar.Variable(name);

    private static Func<Scalar, Scalar> UnitSimplifier(params string[][] units)
    {
        var relations = SideRelations.Trigonometric;
        foreach (var unit in units)
        {
            var norm = unit.Select(V).Aggregate(Scalar.Zero, (sum, x) => sum + x * x);
            relations = relations.With(norm, Scalar.One, V(unit[0]) * V(unit[0]));
        }
        var assumptions = Assumptions.None.WithRelations(relations);
        var cas = new RuleBasedCas();
        return s => cas.Simplify(s, assumptions);
    }

    private static Dictionary<string, double> RunBlock(CodeBlock block, Dictionary<string, double> inputs)
    {
        var values = new Dictionary<string, double>(inputs, StringComparer.Ordinal);
        foreach (var s in block.Statements.Cast<AssignmentStatement>())
            values[s.Target] = ExprEvaluator.Evaluate(s.Value, values);
        return values;
    }

    private static double[] UnitVector(Random random, int n)
    {
        var v = Enumerable.Range(0, n).Select(_ => random.NextDouble() * 2 - 1).ToArray();
        var norm = Math.Sqrt(v.Sum(x => x * x));
        return v.Select(x => x / norm).ToArray();
    }

    [Fact]
    public void Root_of_the_reduced_complement_of_a_dot_product_reads_one_minus_its_square()
    {
        // two unit complex numbers a + ib, c + id: (ad − bc)² = 1 − (ac + bd)² once a² + b² = c² + d² = 1
        var simplify = UnitSimplifier(["a", "b"], ["c", "d"]);
        var dot = V("a") * V("c") + V("b") * V("d");
        var cross = V("a") * V("d") - V("b") * V("c");
        var reduced = simplify(cross * cross);
        Assert.Equal(AtomKind.Sqrt, Scalar.Sqrt(reduced).Terms.Single().Monomial.Factors.Single().Atom.Kind); // no square to take the root of
        var inputs = new[] { "a", "b", "c", "d" }.ToDictionary(k => k, k => k, StringComparer.Ordinal);
        var outputs = new Dictionary<string, string>(StringComparer.Ordinal) { ["n"] = "n", ["s"] = "s" };
        var request = new CodeGenerationRequest(_ => new SymbolicProgram(
            [new SymbolicOutput("n", Scalar.Sqrt(reduced)), new SymbolicOutput("s", Scalar.Abs(dot))]), inputs, outputs)
        {
            Simplify = simplify,
            Join = JoinMode.Joined,
        };

        var result = CodeGenerator.Generate(request);

        // t = a·c + b·d; n = √(1 − t·t); s = |t|
        Assert.Equal((2, 3, 0, 2), (result.Statistics.Additions, result.Statistics.Multiplications, result.Statistics.Divisions, result.Statistics.Calls));
        var random = new Random(3);
        for (var i = 0; i < 20; i++)
        {
            var (z, w) = (UnitVector(random, 2), UnitVector(random, 2));
            var values = RunBlock(result.Block, new() { ["a"] = z[0], ["b"] = z[1], ["c"] = w[0], ["d"] = w[1] });
            Assert.Equal(Math.Abs(z[0] * w[1] - z[1] * w[0]), values["n"], 12);
            Assert.Equal(Math.Abs(z[0] * w[0] + z[1] * w[1]), values["s"], 12);
        }
    }

    private static readonly string[] R1 = ["w1", "x1", "y1", "z1"], R2 = ["w2", "x2", "y2", "z2"];
    private static readonly string[] Blades = ["1", "e2^e3", "e3^e1", "e1^e2"];

    /// <summary>
    /// e^{α log(R₂R̃₁)} R₁ with log R = ⟨R⟩₂/‖⟨R⟩₂‖ θ and e^B = cos φ + sin φ/φ B, where θ is
    /// atan(‖⟨R⟩₂‖/‖⟨R⟩₀‖) (the short way round) or, when principal, atan2(‖⟨R⟩₂‖, ⟨R⟩₀).
    /// </summary>
    private static CodeGenerationResult Interpolation(bool principal)
    {
        var simplify = UnitSimplifier(R1, R2);
        Multivector<Scalar> Rotor(string[] c) => Multivector<Scalar>.FromScalar(E3, V(c[0]))
            + Multivector<Scalar>.Basis(E3, "e2^e3") * V(c[1])
            + Multivector<Scalar>.Basis(E3, "e3^e1") * V(c[2])
            + Multivector<Scalar>.Basis(E3, "e1^e2") * V(c[3]);
        var inputs = R1.Concat(R2).Append("alpha").ToDictionary(k => k, k => k, StringComparer.Ordinal);
        var outputs = Blades.ToDictionary(b => b, b => $"r{b}", StringComparer.Ordinal);
        var request = new CodeGenerationRequest(_ =>
        {
            var q = Rotor(R2).Gp(Rotor(R1).Inverse());
            var b2 = q.Grade(2);
            var n2 = b2.Norm();
            var theta = principal ? Scalar.Atan2(n2, q.ScalarPart) : Scalar.Atan(n2 / q.Grade(0).Norm());
            var b = b2 / n2 * theta * V("alpha");
            var phi = Scalar.Sqrt(-b.Sp(b).ScalarPart);
            var exp = Multivector<Scalar>.FromScalar(E3, Scalar.Cos(phi)) + b * (Scalar.Sin(phi) / phi);
            var r = exp.Gp(Rotor(R1));
            return new SymbolicProgram(Blades.Select(bl => (SymbolicStatement)new SymbolicOutput(bl, bl == "1" ? r.ScalarPart : r[bl])).ToList());
        }, inputs, outputs)
        {
            Simplify = simplify,
            Join = JoinMode.Joined,
        };
        return CodeGenerator.Generate(request);
    }

    /// <summary>Runs the block on random unit rotors against slerp, Ω from R₁·R₂ or from its absolute value.</summary>
    private static void AssertSlerp(CodeBlock block, bool shortWay)
    {
        var random = new Random(8);
        for (var i = 0; i < 20; i++)
        {
            var (p, q) = (UnitVector(random, 4), UnitVector(random, 4));
            var alpha = random.NextDouble();
            var values = new Dictionary<string, double> { ["alpha"] = alpha };
            for (var k = 0; k < 4; k++) (values[R1[k]], values[R2[k]]) = (p[k], q[k]);
            var got = RunBlock(block, values);
            var s = p.Zip(q, (x, y) => x * y).Sum();
            var omega = Math.Atan2(Math.Sqrt(1 - s * s), shortWay ? Math.Abs(s) : s);
            var weight2 = Math.Sin(alpha * omega) / Math.Sqrt(1 - s * s);
            var weight1 = Math.Cos(alpha * omega) - weight2 * s;
            for (var k = 0; k < 4; k++) Assert.Equal(weight1 * p[k] + weight2 * q[k], got[Blades[k]], 9);
        }
    }

    [Fact]
    public void Rotor_interpolation_the_short_way_reads_the_dot_product_once()
    {
        var result = Interpolation(principal: false);

        // s = R₁·R₂ (4 mul, 3 add), √(1 − s²), atan2, |s|, αΩ, sin, cos, k = sin/|B|, c = cos − k s, c R₁ + k R₂
        Assert.Equal((9, 15, 1, 5), (result.Statistics.Additions, result.Statistics.Multiplications, result.Statistics.Divisions, result.Statistics.Calls));
        AssertSlerp(result.Block, shortWay: true);
    }

    [Fact]
    public void Rotor_interpolation_through_the_principal_logarithm_costs_no_more_than_slerp()
    {
        var result = Interpolation(principal: true);

        // atan2(√(1 − s²), s) is acos s, and the root its sine: s, Ω = acos s, sin Ω, αΩ, sin and cos, k, c, c R₁ + k R₂
        Assert.Equal((8, 14, 1, 4), (result.Statistics.Additions, result.Statistics.Multiplications, result.Statistics.Divisions, result.Statistics.Calls));
        AssertSlerp(result.Block, shortWay: false);
    }
}
