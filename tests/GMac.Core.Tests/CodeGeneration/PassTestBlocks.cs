using GMac.Core.CodeGeneration;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>Small code blocks over the inputs a, b, c, d, and the value check every pass test makes.</summary>
internal static class PassTestBlocks
{
    internal static readonly Expr A = Variable("a"), B = Variable("b"), C = Variable("c"), D = Variable("d");

    internal static CodeBlock Block(params CodeStatement[] statements) =>
        new(statements,
            new[] { "a", "b", "c", "d" }.ToDictionary(k => k, k => k, StringComparer.Ordinal),
            statements.OfType<AssignmentStatement>().Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target, StringComparer.Ordinal));

    internal static AssignmentStatement Temp(string name, Expr value) => new(name, value, false);
    internal static AssignmentStatement Out(string name, Expr value) => new(name, value, true);

    /// <summary>Every pass must keep the outputs' values: checked on random inputs.</summary>
    internal static void AssertSameOutputs(CodeBlock before, CodeBlock after)
    {
        var random = new Random(80);
        for (var i = 0; i < 20; i++)
        {
            var inputs = new[] { "a", "b", "c", "d" }.ToDictionary(k => k, _ => random.NextDouble() * 4 + 0.5, StringComparer.Ordinal);
            var expected = before.Evaluate(inputs);
            var actual = after.Evaluate(inputs);
            Assert.Equal(expected.Keys.Order(), actual.Keys.Order());
            foreach (var (k, v) in expected)
                Assert.True(Math.Abs(v - actual[k]) <= 1e-11 * Math.Max(1, Math.Abs(v)), $"{k}: {v} before, {actual[k]} after");
        }
    }
}
