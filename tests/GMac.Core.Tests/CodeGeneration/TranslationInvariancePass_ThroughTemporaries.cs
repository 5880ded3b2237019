using GMac.Core.CodeGeneration;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class TranslationInvariancePass_ThroughTemporaries
{
    private static readonly string[] Inputs = ["ax", "ay", "az", "bx", "by", "bz"];

    /// <summary>
    /// The rejection w = b − k a (k = a·b / a·a) and n = a × w, as Gram–Schmidt computes them: n is
    /// a × b, the k a × a cancelling, so over the differences it is a × (b − a) and needs no k.
    /// </summary>
    private static CodeBlock Rejection()
    {
        static Expr V(string n) => Variable(n);
        var statements = new List<CodeStatement>
        {
            new AssignmentStatement("k", Quotient(Sum(Product(V("ax"), V("bx")), Product(V("ay"), V("by")), Product(V("az"), V("bz"))),
                Sum(Product(V("ax"), V("ax")), Product(V("ay"), V("ay")), Product(V("az"), V("az")))), false),
        };
        foreach (var c in new[] { "x", "y", "z" })
            statements.Add(new AssignmentStatement("w" + c, Difference(V("b" + c), Product(V("k"), V("a" + c))), false));
        statements.Add(new AssignmentStatement("nx", Difference(Product(V("ay"), V("wz")), Product(V("az"), V("wy"))), true));
        statements.Add(new AssignmentStatement("ny", Difference(Product(V("az"), V("wx")), Product(V("ax"), V("wz"))), true));
        statements.Add(new AssignmentStatement("nz", Difference(Product(V("ax"), V("wy")), Product(V("ay"), V("wx"))), true));
        foreach (var c in new[] { "x", "y", "z" })
            statements.Add(new AssignmentStatement("o" + c, V("w" + c), true));
        var outputs = new[] { "nx", "ny", "nz", "ox", "oy", "oz" }.ToDictionary(n => n, n => n, StringComparer.Ordinal);
        return new CodeBlock(statements, Inputs.ToDictionary(n => n, n => n, StringComparer.Ordinal), outputs)
        {
            Points = [new InputPoint("v", ["ax", "ay", "az"]), new InputPoint("v", ["bx", "by", "bz"])],
        };
    }

    /// <summary>Whether the value of <paramref name="e"/> waits for a division, through the temporaries it reads.</summary>
    private static bool WaitsForDivision(Expr e, CodeBlock block) => e.DescendantsAndSelf().Any(node => node switch
    {
        QuotientExpr => true,
        VariableExpr v => block.Temporaries.FirstOrDefault(t => t.Target == v.Name) is { } t && WaitsForDivision(t.Value, block),
        _ => false,
    });

    [Fact]
    public void A_cross_product_with_a_rejection_is_written_over_the_difference_of_the_points_and_no_longer_waits_for_the_division()
    {
        var block = Optimizer.Reduce(Rejection(), differencesEverywhere: true);
        foreach (var n in new[] { "nx", "ny", "nz" })
            Assert.False(WaitsForDivision(block.Statements.OfType<AssignmentStatement>().Single(s => s.Target == n).Value, block), n);
        var random = new Random(3);
        for (var i = 0; i < 20; i++)
        {
            var x = Inputs.ToDictionary(n => n, _ => random.NextDouble() * 2 - 1, StringComparer.Ordinal);
            var values = block.Evaluate(x);
            // a × b, and the rejection itself unchanged
            Assert.Equal(x["ay"] * x["bz"] - x["az"] * x["by"], values["nx"], 1e-12);
            Assert.Equal(x["az"] * x["bx"] - x["ax"] * x["bz"], values["ny"], 1e-12);
            Assert.Equal(x["ax"] * x["by"] - x["ay"] * x["bx"], values["nz"], 1e-12);
            var k = (x["ax"] * x["bx"] + x["ay"] * x["by"] + x["az"] * x["bz"]) / (x["ax"] * x["ax"] + x["ay"] * x["ay"] + x["az"] * x["az"]);
            Assert.Equal(x["bx"] - k * x["ax"], values["ox"], 1e-12);
        }
    }

    [Fact]
    public void Without_differences_everywhere_the_cross_product_keeps_reading_the_rejection()
    {
        var block = Optimizer.Reduce(Rejection());
        Assert.True(WaitsForDivision(block.Statements.OfType<AssignmentStatement>().Single(s => s.Target == "nz").Value, block));
    }
}
