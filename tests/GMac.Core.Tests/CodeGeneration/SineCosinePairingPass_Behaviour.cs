using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class SineCosinePairingPass_Behaviour
{
    private static readonly string[] Names = ["a", "b", "x"];
    private static readonly Expr A = Variable("a"), B = Variable("b"), X = Variable("x");

    private static CodeBlock Block(params CodeStatement[] statements) =>
        new(statements, Names.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            statements.OfType<AssignmentStatement>().Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target + "Target", StringComparer.Ordinal));

    private static void AssertSameValues(CodeBlock before, CodeBlock after)
    {
        var random = new Random(5);
        for (var i = 0; i < 30; i++)
        {
            var inputs = Names.ToDictionary(n => n, _ => 4 * random.NextDouble() - 2, StringComparer.Ordinal);
            var expected = before.Evaluate(inputs);
            var actual = after.Evaluate(inputs);
            foreach (var (k, v) in expected)
                Assert.Equal(v, actual[k], 1e-14);
        }
    }

    private static int Calls(CodeBlock block, string function) => block.Statements
        .SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf())
        .Count(n => n is CallExpr c && c.Function == function);

    [Fact]
    public void Sine_and_cosine_inside_larger_expressions_get_a_temporary_each_and_one_sincos()
    {
        // d.x = −cos a · sin b · x, d.y = sin a · x, d.z = cos a · cos b: what a sphere's point looks like.
        var block = Block(
            new AssignmentStatement("dx", Product(Negate(Call("cos", A)), Call("sin", B), X), true),
            new AssignmentStatement("dy", Product(Call("sin", A), X), true),
            new AssignmentStatement("dz", Product(Call("cos", A), Call("cos", B)), true));
        var paired = new SineCosinePairingPass().Run(block);

        AssertSameValues(block, paired);
        // cos a was written twice: one temporary now serves both.
        Assert.Equal(block.Statistics().Multiplications, paired.Statistics().Multiplications);
        Assert.Equal(4, paired.Statistics().Calls);
        foreach (var f in new[] { "sin", "cos" })
            Assert.Equal(2, Calls(paired, f));
        var code = BlockText.Of(paired);
        // each call is a temporary of its own, which the emitter can compute with its partner
        foreach (var call in new[] { "sin(a)", "cos(a)", "sin(b)", "cos(b)" })
            Assert.Contains($" = {call};", code);
    }

    [Fact]
    public void A_temporary_that_already_holds_the_call_is_read_instead_of_a_new_one()
    {
        var block = Block(
            new AssignmentStatement("s", Call("sin", A), false),
            new AssignmentStatement("o", Sum(Variable("s"), Product(Call("cos", A), X), Product(Call("sin", A), B)), true));
        var paired = new SineCosinePairingPass().Run(block);

        AssertSameValues(block, paired);
        Assert.Equal(1, Calls(paired, "sin"));
        Assert.Equal(1, Calls(paired, "cos"));
        Assert.Contains(paired.Statements, s => s is AssignmentStatement { Target: "s" });
        Assert.Equal("s = sin(a);\ntrig0 = cos(a);\noTarget = s + trig0 * x + s * b;\n", BlockText.Of(paired));
    }

    [Fact]
    public void A_lone_sine_or_cosines_of_other_arguments_are_left_alone()
    {
        var block = Block(
            new AssignmentStatement("o", Product(Call("sin", A), Call("cos", B)), true),
            new AssignmentStatement("p", Call("cos", Sum(A, B)), true));
        var paired = new SineCosinePairingPass().Run(block);
        Assert.Same(block, paired);
    }

    [Fact]
    public void The_optimizer_pairs_the_calls_of_a_turned_vector()
    {
        // x rotated by angle a in the plane: (x cos a, x sin a), written as two outputs.
        var block = Block(
            new AssignmentStatement("u", Product(X, Call("cos", A)), true),
            new AssignmentStatement("v", Product(X, Call("sin", A)), true));
        var optimized = Optimizer.Optimize(block);
        var code = BlockText.Of(optimized);
        Assert.Contains(" = sin(a);", code);
        Assert.Contains(" = cos(a);", code);
        Assert.Equal(1, Calls(optimized, "sin"));
    }
}
