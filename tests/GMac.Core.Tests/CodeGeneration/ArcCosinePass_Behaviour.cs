using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class ArcCosinePass_Behaviour
{
    private static readonly Expr N = Variable("n");

    private static Expr Complement(Expr u) => Call("sqrt", Difference(ConstantExpr.One, Product(u, u)));

    /// <summary>Outputs before and after on cosines a in (−1, 1) and weights b.</summary>
    private static void AssertSameValues(CodeBlock before, CodeBlock after, double tolerance)
    {
        var random = new Random(31);
        for (var i = 0; i < 50; i++)
        {
            var inputs = new Dictionary<string, double>(StringComparer.Ordinal)
            {
                ["a"] = random.NextDouble() * 1.998 - 0.999, ["b"] = random.NextDouble(), ["c"] = 0, ["d"] = 0,
            };
            var expected = before.Evaluate(inputs);
            var actual = after.Evaluate(inputs);
            foreach (var (k, v) in expected)
                Assert.True(Math.Abs(v - actual[k]) <= tolerance * Math.Max(1, Math.Abs(v)), $"{k}: {v} before, {actual[k]} after");
        }
    }

    [Fact]
    public void Slerp_weights_read_the_angle_from_acos_and_divide_by_its_sine()
    {
        // n = √(1 − a²); θ = atan2(n, a); o = sin(bθ)/n: the weight of spherical interpolation
        var before = Block(
            Temp("n", Complement(A)),
            Out("o", Quotient(Call("sin", Product(Call("atan2", N, A), B)), N)));
        var after = new ArcCosinePass().Run(before);

        Assert.Equal("temp acs0 = acos(a);\ntemp n = sin(acs0);\no = sin(acs0 * b) / n;", PassText(after));
        var (was, now) = (before.Statistics(), after.Statistics());
        Assert.Equal((1, 2, 1, 3), (was.Additions, was.Multiplications, was.Divisions, was.Calls));
        Assert.Equal((0, 1, 1, 3), (now.Additions, now.Multiplications, now.Divisions, now.Calls));
        AssertSameValues(before, after, 1e-12);
    }

    [Fact]
    public void A_root_written_inside_atan2_becomes_acos_alone()
    {
        var before = Block(Out("o", Call("atan2", Complement(A), A)));
        var after = new ArcCosinePass().Run(before);

        Assert.Equal("o = acos(a);", PassText(after));
        AssertSameValues(before, after, 1e-15);
    }

    [Theory]
    [InlineData("other cosine")]
    [InlineData("other constant")]
    [InlineData("other function")]
    public void Roots_that_are_not_the_sine_of_the_angle_are_left_alone(string variant)
    {
        // atan2(√(1 − a²), b), atan2(√(2 − a²), a) and atan2(|1 − a²|, a) are no arc cosines
        var root = variant switch
        {
            "other constant" => Call("sqrt", Difference(Constant(2), Product(A, A))),
            "other function" => Call("abs", Difference(ConstantExpr.One, Product(A, A))),
            _ => Complement(A),
        };
        var before = Block(Out("o", Call("atan2", root, variant == "other cosine" ? B : A)));
        Assert.Same(before, new ArcCosinePass().Run(before));
    }

    private static string PassText(CodeBlock block) => block.ToString().ReplaceLineEndings("\n");
}
