using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// A sum whose value is c·(t₁² + … + tₖ²) for temporaries the block already computes is read as
/// that. |a ∧ b|² reaches the block expanded (|a|²|b|² − (a·b)², a dozen products) while the
/// block names the components of a × b for another use, where their squares cost 2k − 1. The
/// candidate sets are the temporaries read together by one sum (the components that a dot
/// product such as (a × b)·c reads) or by one statement; a sum is compared with each through its
/// polynomial value (<see cref="PolynomialValues"/>), so the rewrite keeps values exactly, and it
/// is taken only where the sum costs more than the squares.
/// </summary>
public sealed class SumOfSquaresPass : IOptimizerPass
{
    private const int MaxSetSize = 8;

    public string Name => "sums of squares of named values";

    public CodeBlock Run(CodeBlock block)
    {
        var position = new Dictionary<string, int>(StringComparer.Ordinal);
        for (var i = 0; i < block.Statements.Count; i++)
            if (block.Statements[i] is AssignmentStatement { IsOutput: false } t) position[t.Target] = i;
        if (position.Count < 2) return block;

        var values = new PolynomialValues(block);
        var squares = CandidateSums(block, position, values);
        if (squares.Count == 0) return block;

        var changed = false;
        var statements = block.Statements.ToArray();
        for (var i = 0; i < statements.Length; i++)
        {
            var index = i;
            var s = statements[i];
            var exprs = s.Expressions.Select(e => BlockRewriting.ReplaceNodes(e, node =>
            {
                if (node is not SumExpr || values.Of(node) is not { } p || p.Terms.Count < 2) return null;
                if (!squares.TryGetValue(Monic(p, out var scale), out var set)) return null;
                if (set.Names.Any(n => position[n] >= index)) return null;
                var replacement = Squares(set.Names, scale / set.Scale);
                return OperationCost(replacement) < OperationCost(node) ? replacement : null;
            })).ToArray();
            if (exprs.Where((e, k) => !ReferenceEquals(e, s.Expressions[k])).Any())
            {
                statements[i] = s.WithExpressions(exprs);
                changed = true;
            }
        }
        return changed ? new DeadCodePass().Run(block.WithStatements(statements)) : block;
    }

    /// <summary>Σ t² for each set of temporaries read together, by its monic value.</summary>
    private static Dictionary<Scalar, (string[] Names, Rational Scale)> CandidateSums(CodeBlock block, Dictionary<string, int> position, PolynomialValues values)
    {
        var sets = new HashSet<string>(StringComparer.Ordinal);
        var sums = new Dictionary<Scalar, (string[] Names, Rational Scale)>();
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
        {
            if (node is not SumExpr && !ReferenceEquals(node, e)) continue;
            var names = node.DescendantsAndSelf().OfType<VariableExpr>().Select(v => v.Name)
                .Where(position.ContainsKey).Distinct().Order(StringComparer.Ordinal).ToArray();
            if (names.Length < 2 || names.Length > MaxSetSize || !sets.Add(string.Join(",", names))) continue;
            var sum = Scalar.Zero;
            foreach (var n in names)
            {
                var v = values.OfName(n);
                sum += v * v;
            }
            if (sum.Terms.Count < 2 || sum.Terms.Count > PolynomialValues.MaxTerms) continue;
            sums.TryAdd(Monic(sum, out var scale), (names, scale));
        }
        return sums;
    }

    /// <summary>p divided by the coefficient of its first term, which is returned in <paramref name="scale"/>.</summary>
    private static Scalar Monic(Scalar p, out Rational scale)
    {
        scale = p.Terms[0].Coefficient;
        return scale == Rational.One ? p : Scalar.Scale(p, Rational.One / scale);
    }

    private static Expr Squares(IEnumerable<string> names, Rational scale)
    {
        var sum = ExprFactory.Sum(names.Select(n => ExprFactory.Product(ExprFactory.Variable(n), ExprFactory.Variable(n))));
        return scale == Rational.One ? sum : ExprFactory.Product(ExprFactory.Constant(scale), sum);
    }

    private static int OperationCost(Expr e) =>
        new CodeBlock([new AssignmentStatement("x", e, true)], new Dictionary<string, string>(), new Dictionary<string, string>()).Statistics().Cost;
}
