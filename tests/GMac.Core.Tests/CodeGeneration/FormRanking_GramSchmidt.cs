using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Accuracy;
using GMac.Core.CodeGeneration.Cost;
using GMac.Core.Symbolic;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// Three forms of Gram–Schmidt by rejections (w2 = v2 − k v1, k = v1·v2 / v1·v1; w3 = s n, s = v3·n / n·n)
/// that differ only in the normal n: the textbook v1 × v2, the generator's former v1 × w2 (after
/// the first division) and v1 × (v2 − v1). Measured on this kind of machine the textbook form is
/// faster than v1 × w2, v1 × (v2 − v1) at least as fast as the textbook and accurate where the
/// vectors share a large common part, where the textbook form is not. The ranking must agree.
/// </summary>
public sealed class FormRanking_GramSchmidt
{
    private enum Normal { Textbook, ThroughRejection, Differences }

    private static Expr V(string name) => Variable(name);

    private static Expr[] Vector(string name) => [V(name + "x"), V(name + "y"), V(name + "z")];

    private static Expr Dot(Expr[] a, Expr[] b) => Sum(Product(a[0], b[0]), Product(a[1], b[1]), Product(a[2], b[2]));

    private static Expr[] Cross(Expr[] a, Expr[] b) =>
    [
        Difference(Product(a[1], b[2]), Product(a[2], b[1])),
        Difference(Product(a[2], b[0]), Product(a[0], b[2])),
        Difference(Product(a[0], b[1]), Product(a[1], b[0])),
    ];

    private static CodeBlock Form(Normal normal)
    {
        var (a, b, c) = (Vector("a"), Vector("b"), Vector("c"));
        var statements = new List<CodeStatement>();
        Expr[] Name(string prefix, Expr[] values)
        {
            for (var i = 0; i < 3; i++) statements.Add(new AssignmentStatement($"{prefix}{i}", values[i], false));
            return [V(prefix + "0"), V(prefix + "1"), V(prefix + "2")];
        }
        statements.Add(new AssignmentStatement("k", Quotient(Dot(a, b), Dot(a, a)), false));
        var w2 = Name("w", [.. Enumerable.Range(0, 3).Select(i => Difference(b[i], Product(V("k"), a[i])))]);
        var n = Name("n", normal switch
        {
            Normal.Textbook => Cross(a, b),
            Normal.ThroughRejection => Cross(a, w2),
            _ => Cross(a, Name("d", [.. Enumerable.Range(0, 3).Select(i => Difference(b[i], a[i]))])),
        });
        statements.Add(new AssignmentStatement("s", Quotient(Dot(c, n), Dot(n, n)), false));
        for (var i = 0; i < 3; i++)
        {
            statements.Add(new AssignmentStatement($"o{i}", a[i], true));
            statements.Add(new AssignmentStatement($"o{i + 3}", w2[i], true));
            statements.Add(new AssignmentStatement($"o{i + 6}", Product(V("s"), n[i]), true));
        }
        var inputs = new[] { "a", "b", "c" }.SelectMany(p => new[] { p + "x", p + "y", p + "z" }).ToDictionary(x => x, x => x, StringComparer.Ordinal);
        return new CodeBlock(statements, inputs, Enumerable.Range(0, 9).ToDictionary(i => $"o{i}", i => $"o{i}", StringComparer.Ordinal));
    }

    [Fact]
    public void The_forms_have_the_operation_counts_and_accuracy_the_ranking_is_about()
    {
        // more operations for the difference form, and the textbook form far less accurate
        Assert.True(Form(Normal.Differences).Statistics().Operations > Form(Normal.ThroughRejection).Statistics().Operations);
        Assert.True(AccuracyProbe.Error(Form(Normal.Textbook)) > AccuracyProbe.Factor * AccuracyProbe.Error(Form(Normal.Differences)));
        Assert.True(AccuracyProbe.Error(Form(Normal.ThroughRejection)) < AccuracyProbe.Factor * AccuracyProbe.Error(Form(Normal.Differences)));
    }

    [Fact]
    public void The_time_model_orders_the_forms_as_measured()
    {
        double Cycles(Normal n) => TimeModel.Estimate(Form(n)).Cycles;
        Assert.True(Cycles(Normal.Textbook) < Cycles(Normal.ThroughRejection));
        Assert.True(Cycles(Normal.Differences) < Cycles(Normal.ThroughRejection));
    }

    [Fact]
    public void The_difference_form_wins_over_the_textbook_form_and_the_form_through_the_rejection()
    {
        Normal[] order = [Normal.Textbook, Normal.ThroughRejection, Normal.Differences];
        foreach (var permutation in Permutations(order))
        {
            var ranked = FormRanking.Rank([.. permutation.Select(Form)], SideRelations.None);
            Assert.Equal(Normal.Differences, permutation[ranked[0]]);
        }
    }

    private static IEnumerable<Normal[]> Permutations(Normal[] items) => items.Length <= 1
        ? [items]
        : items.SelectMany((x, i) => Permutations([.. items.Where((_, j) => j != i)]).Select(rest => (Normal[])[x, .. rest]));
}
