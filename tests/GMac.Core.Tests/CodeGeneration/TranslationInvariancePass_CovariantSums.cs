using GMac.Core.CodeGeneration;
using GMac.Core.Numerics;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class TranslationInvariancePass_CovariantSums
{
    private static readonly InputPoint A = new("p", ["ax", "ay", "az"], IsPosition: true);
    private static readonly InputPoint B = new("p", ["bx", "by", "bz"], IsPosition: true);

    private static Expr Square(string v) => Product(Variable(v), Variable(v));

    [Fact]
    public void Half_difference_of_squared_norms_is_half_the_difference_dotted_with_the_sum()
    {
        // ½(|b|² − |a|²) = ½ (b − a)·(b + a): three subtractions, three additions, three products,
        // two additions and one scaling, 12 operations; the sum b + a is read from the points.
        var expanded = Product(Constant(new Rational(1, 2)), Sum(Square("bx"), Square("by"), Square("bz"),
            Negate(Square("ax")), Negate(Square("ay")), Negate(Square("az"))));
        var block = Optimizer.Reduce(new CodeBlock([new AssignmentStatement("h", expanded, true)],
            new[] { "ax", "ay", "az", "bx", "by", "bz" }.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            new Dictionary<string, string>(StringComparer.Ordinal) { ["h"] = "h" }) { Points = [A, B] }, differencesEverywhere: true);
        Assert.InRange(block.Statistics().Operations, 0, 12);
        var random = new Random(5);
        for (var i = 0; i < 20; i++)
        {
            var x = block.InputText.Keys.ToDictionary(n => n, _ => 1e4 + random.NextDouble(), StringComparer.Ordinal);
            double a2 = x["ax"] * x["ax"] + x["ay"] * x["ay"] + x["az"] * x["az"], b2 = x["bx"] * x["bx"] + x["by"] * x["by"] + x["bz"] * x["bz"];
            Assert.Equal(0.5 * (b2 - a2), block.Evaluate(x)["h"], 1e-9 * Math.Abs(b2));
        }
    }
}
