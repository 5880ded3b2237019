using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using GMac.Core.CodeGeneration.Rewrites;
using GMac.Core.Symbolic;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// The rewrites that go past canonical polynomials: each keeps every value (checked on random
/// inputs against the expression it rewrote) and reaches an exact operation count on a small case.
/// </summary>
public class Rewrites_BeyondPolynomials
{
    private static Scalar V(string name) => Scalar.Variable(name);

    private static void AssertSameValue(Scalar expected, Scalar actual, params string[] variables)
    {
        var random = new Random(14);
        for (var i = 0; i < 20; i++)
        {
            var values = variables.ToDictionary(v => v, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var (e, a) = (expected.Evaluate(values), actual.Evaluate(values));
            Assert.True(Math.Abs(e - a) <= 1e-12 * Math.Max(1, Math.Abs(e)), $"{e} expected, {a} after the rewrite");
        }
    }

    private static void AssertSameValue(Scalar expected, Expr actual, params string[] variables)
    {
        var random = new Random(15);
        for (var i = 0; i < 20; i++)
        {
            var values = variables.ToDictionary(v => v, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var (e, a) = (expected.Evaluate(values), ExprEvaluator.Evaluate(actual, values));
            Assert.True(Math.Abs(e - a) <= 1e-12 * Math.Max(1, Math.Abs(e)), $"{e} expected, {a} after lowering");
        }
    }

    private static CodeStatistics StatisticsOf(Expr e) =>
        new CodeBlock([new AssignmentStatement("y", e, true)], new Dictionary<string, string>(), new Dictionary<string, string>()).Statistics();

    [Fact]
    public void Norm_cancellation_takes_the_multiple_of_the_norm_out_of_the_fraction()
    {
        // VortexS, first coordinate: (ω (p·a) a₁ + γ |a|² (a₂p₃ − a₃p₂)) / |a|²
        var norm = V("a1") * V("a1") + V("a2") * V("a2") + V("a3") * V("a3");
        var dot = V("p1") * V("a1") + V("p2") * V("a2") + V("p3") * V("a3");
        var cross = V("a2") * V("p3") - V("a3") * V("p2");
        var before = (V("w") * dot * V("a1") + V("g") * norm * cross) / norm;

        var after = PartialInverseCancellation.Apply(before);

        Assert.Same(V("g") * cross + V("w") * dot * V("a1") / norm, after);
        AssertSameValue(before, after, "a1", "a2", "a3", "p1", "p2", "p3", "w", "g");
    }

    [Fact]
    public void Norm_cancellation_leaves_a_fraction_with_no_multiple_of_its_denominator()
    {
        var norm = V("a") * V("a") + V("b") * V("b");
        var before = (V("a") * V("c") + V("b") * V("d")) / norm;
        Assert.Same(before, PartialInverseCancellation.Apply(before));
    }

    [Fact]
    public void Angle_zero_split_lowers_a_rotated_coordinate_to_the_versine_form()
    {
        // first coordinate of a rotation about a unit axis k in the plane of e1, e2, expanded:
        // k₁(k·x) + cos φ (x₁ − k₁(k·x)) − sin φ k₂ x₃, which is x₁ at φ = 0
        var (k1, k2, x1, x2, x3) = (V("k1"), V("k2"), V("x1"), V("x2"), V("x3"));
        var projection = k1 * (k1 * x1 + k2 * x2);
        var cos = Scalar.Cos(V("phi"));
        var before = projection + cos * (x1 - projection) - Scalar.Sin(V("phi")) * k2 * x3;

        Assert.True(AngleZeroSplit.TrySplit(before, out var atZero, out _, out var cofactor));
        Assert.Same(x1 - Scalar.Sin(V("phi")) * k2 * x3, atZero);
        Assert.Same(x1 - projection, cofactor);

        var lowered = ScalarLowering.Lower(before);
        AssertSameValue(before, lowered, "k1", "k2", "x1", "x2", "x3", "phi");
        // x₁ − sin φ k₂x₃ + (cos φ − 1)(x₁ − k₁(k₁x₁ + k₂x₂)): the two functions once each
        var stats = StatisticsOf(lowered);
        Assert.Equal((5, 6, 0, 2), (stats.Additions, stats.Multiplications, stats.Divisions, stats.Calls));
    }

    [Fact]
    public void Square_root_reciprocal_pass_divides_once_for_a_root_and_its_square()
    {
        var norm = Sum(Product(A, A), Product(B, B));
        var before = Block(
            Temp("n", norm),
            Out("u", Quotient(ConstantExpr.One, Call("sqrt", Variable("n")))),
            Out("v", Quotient(D, Variable("n"))));

        var after = new SquareRootReciprocalPass().Run(before);

        AssertSameOutputs(before, after);
        var (b, a) = (before.Statistics(), after.Statistics());
        // 1/√n becomes √(1/n): the second division is a product
        Assert.Equal((1, 2, 2, 1), (b.Additions, b.Multiplications, b.Divisions, b.Calls));
        Assert.Equal((1, 3, 1, 1), (a.Additions, a.Multiplications, a.Divisions, a.Calls));
    }

    [Fact]
    public void Constant_absorption_turns_the_rotor_matrix_doublings_into_three_additions()
    {
        // the rotation matrix of the unit quaternion (a, b, c, d) as the generator lowers it
        Expr Two(Expr e) => Product(Constant(2), e);
        Expr T(string n) => Variable(n);
        var before = Block(
            Temp("bc", Product(B, C)), Temp("ad", Product(A, D)), Temp("bd", Product(B, D)),
            Temp("ac", Product(A, C)), Temp("cd", Product(C, D)), Temp("ab", Product(A, B)),
            Temp("cc", Product(C, C)), Temp("dd", Product(D, D)), Temp("bb", Product(B, B)),
            Out("m11", Difference(Constant(1), Two(Sum(T("cc"), T("dd"))))),
            Out("m12", Two(Difference(T("bc"), T("ad")))),
            Out("m13", Two(Sum(T("bd"), T("ac")))),
            Out("m21", Two(Sum(T("bc"), T("ad")))),
            Out("m22", Difference(Constant(1), Two(Sum(T("bb"), T("dd"))))),
            Out("m23", Two(Difference(T("cd"), T("ab")))),
            Out("m31", Two(Difference(T("bd"), T("ac")))),
            Out("m32", Two(Sum(T("cd"), T("ab")))),
            Out("m33", Difference(Constant(1), Two(Sum(T("bb"), T("cc"))))));

        var after = new ConstantAbsorptionPass().Run(before);

        AssertSameOutputs(before, after);
        var (b, a) = (before.Statistics(), after.Statistics());
        Assert.Equal((12, 18), (b.Additions, b.Multiplications));
        Assert.Equal((15, 9), (a.Additions, a.Multiplications));
    }

    [Fact]
    public void Constant_absorption_leaves_a_constant_whose_product_is_read_elsewhere()
    {
        var before = Block(
            Temp("ab", Product(A, B)),
            Out("u", Product(Constant(2), Sum(Variable("ab"), C))),
            Out("v", Sum(Variable("ab"), D)));
        Assert.Same(before, new ConstantAbsorptionPass().Run(before));
    }

    [Fact]
    public void Lowering_takes_out_first_the_atoms_fewer_outputs_read_so_the_rest_is_shared()
    {
        // o1 = p(ac − bd) + q(ad + bc), o2 = r(ac − bd) + s(ad + bc): every atom is in two terms of
        // each output; taking p, q, r, s out first leaves ac − bd and ad + bc to share.
        Scalar P(string n) => V(n);
        var (re, im) = (P("a") * P("c") - P("b") * P("d"), P("a") * P("d") + P("b") * P("c"));
        var o1 = P("p") * re + P("q") * im;
        var o2 = P("r") * re + P("s") * im;
        var names = new[] { "a", "b", "c", "d", "p", "q", "r", "s" };
        var request = new CodeGenerationRequest(_ => new SymbolicProgram([new SymbolicOutput("o1", o1), new SymbolicOutput("o2", o2)]),
            names.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            new Dictionary<string, string>(StringComparer.Ordinal) { ["o1"] = "o1", ["o2"] = "o2" }) { Join = JoinMode.Joined };

        var block = CodeGenerator.Generate(request).Block;

        var stats = block.Statistics();
        Assert.Equal((4, 8), (stats.Additions, stats.Multiplications));
        var random = new Random(16);
        for (var i = 0; i < 10; i++)
        {
            var values = names.ToDictionary(n => n, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var outputs = block.Evaluate(values);
            Assert.Equal(o1.Evaluate(values), outputs["o1"], 12);
            Assert.Equal(o2.Evaluate(values), outputs["o2"], 12);
        }
    }
    [Fact]
    public void Value_numbering_finds_a_wedge_that_a_rejection_leaves_unchanged()
    {
        // t1 = (a, b) ∧ rejection of (c, d) from (a, b) = (a, b) ∧ (c, d) = t2, through a division
        var k = Quotient(Sum(Product(A, C), Product(B, D)), Sum(Product(A, A), Product(B, B)));
        var before = Block(
            Temp("t2", Difference(Product(A, D), Product(B, C))),
            Temp("k", k),
            Temp("p", Difference(C, Product(A, Variable("k")))),
            Temp("q", Difference(D, Product(B, Variable("k")))),
            Temp("t1", Difference(Product(A, Variable("q")), Product(B, Variable("p")))),
            Out("o1", Product(Variable("t1"), C)),
            Out("o2", Product(Variable("t2"), D)));

        var after = new DeadCodePass().Run(new AlgebraicValueNumberingPass().Run(before));

        AssertSameOutputs(before, after);
        var (b, a) = (before.Statistics(), after.Statistics());
        Assert.Equal((6, 12, 1), (b.Additions, b.Multiplications, b.Divisions));
        Assert.Equal((1, 4, 0), (a.Additions, a.Multiplications, a.Divisions));
    }

    [Fact]
    public void Value_numbering_keeps_temporaries_whose_values_differ()
    {
        var before = Block(
            Temp("t1", Difference(Product(A, D), Product(B, C))),
            Temp("t2", Sum(Product(A, D), Product(B, C))),
            Out("o", Product(Variable("t1"), Variable("t2"))));
        Assert.Same(before, new AlgebraicValueNumberingPass().Run(before));
    }
}
