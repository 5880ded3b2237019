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
        if (block.Statements.Any(s => s is VerbatimStatement)) return block;
        var position = new Dictionary<string, int>(StringComparer.Ordinal);
        for (var i = 0; i < block.Statements.Count; i++)
            if (block.Statements[i] is AssignmentStatement { IsOutput: false } t) position[t.Target] = i;
        if (position.Count < 2) return block;

        // Two numeric samples rule out almost every (sum, set) pair before any polynomial is expanded.
        var samples = new[] { Sample(block, 1), Sample(block, 2) };
        var sets = CandidateSets(block, position, samples);
        if (sets.Count == 0) return block;

        var values = new PolynomialValues(block);
        var changed = false;
        var statements = block.Statements.ToArray();
        for (var i = 0; i < statements.Length; i++)
        {
            var index = i;
            var s = statements[i];
            var exprs = s.Expressions.Select(e => BlockRewriting.ReplaceNodes(e, node =>
                node is SumExpr sum && Match(sum, index, sets, position, samples, values) is { } replacement ? replacement : null)).ToArray();
            if (exprs.Where((e, k) => !ReferenceEquals(e, s.Expressions[k])).Any())
            {
                statements[i] = s.WithExpressions(exprs);
                changed = true;
            }
        }
        return changed ? new DeadCodePass().Run(block.WithStatements(statements)) : block;
    }

    /// <summary>A set of temporaries read together, with Σ t² at each sample.</summary>
    private sealed record CandidateSet(string[] Names, double[] Sampled);

    /// <summary>c·Σ t² for the first set whose sum of squares the node equals exactly, when that costs less.</summary>
    private static Expr? Match(SumExpr node, int index, List<CandidateSet> sets, Dictionary<string, int> position, Dictionary<string, double>[] samples, PolynomialValues values)
    {
        var sampled = samples.Select(v => Evaluate(node, v)).ToArray();
        if (sampled.Any(x => !double.IsFinite(x) || x == 0)) return null;
        Scalar? p = null;
        foreach (var set in sets)
        {
            var ratio = sampled[0] / set.Sampled[0];
            if (Math.Abs(sampled[1] / set.Sampled[1] - ratio) > 1e-9 * Math.Abs(ratio)) continue;
            if (set.Names.Any(n => position[n] >= index)) continue;
            p ??= values.Of(node);
            if (p is null || p.Terms.Count < 2) return null;
            var squares = Scalar.Zero;
            foreach (var n in set.Names)
            {
                var v = values.OfName(n);
                squares += v * v;
            }
            if (squares.Terms.Count != p.Terms.Count) continue;
            var scale = p.Terms[0].Coefficient / squares.Terms[0].Coefficient;
            if (Scalar.Scale(squares, scale) != p) continue;
            var replacement = Squares(set.Names, scale);
            return OperationCost(replacement) < OperationCost(node) ? replacement : null;
        }
        return null;
    }

    /// <summary>The sets of two or more temporaries read by one sum or one statement, with their sampled sums of squares.</summary>
    private static List<CandidateSet> CandidateSets(CodeBlock block, Dictionary<string, int> position, Dictionary<string, double>[] samples)
    {
        var seen = new HashSet<string>(StringComparer.Ordinal);
        var sets = new List<CandidateSet>();
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
        {
            if (node is not SumExpr && !ReferenceEquals(node, e)) continue;
            var names = node.DescendantsAndSelf().OfType<VariableExpr>().Select(v => v.Name)
                .Where(position.ContainsKey).Distinct().Order(StringComparer.Ordinal).ToArray();
            if (names.Length < 2 || names.Length > MaxSetSize || !seen.Add(string.Join(",", names))) continue;
            var sampled = samples.Select(v => names.Sum(n => v[n] * v[n])).ToArray();
            if (sampled.All(x => double.IsFinite(x) && x != 0)) sets.Add(new CandidateSet(names, sampled));
        }
        return sets;
    }

    /// <summary>Every name of the block at one pseudo-random point (inputs in [0.5, 2]).</summary>
    private static Dictionary<string, double> Sample(CodeBlock block, int seed)
    {
        var random = new Random(seed);
        var values = block.InputText.Keys.Order(StringComparer.Ordinal).ToDictionary(k => k, _ => 0.5 + 1.5 * random.NextDouble(), StringComparer.Ordinal);
        foreach (var a in block.Statements.OfType<AssignmentStatement>())
            values[a.Target] = Evaluate(a.Value, values);
        return values;
    }

    private static double Evaluate(Expr e, Dictionary<string, double> values)
    {
        try
        {
            return ExprEvaluator.Evaluate(e, values);
        }
        catch (Exception ex) when (ex is KeyNotFoundException or InvalidOperationException or ArgumentException)
        {
            return double.NaN; // a name or function the evaluator does not know: never matches
        }
    }

    private static Expr Squares(IEnumerable<string> names, Rational scale)
    {
        var sum = ExprFactory.Sum(names.Select(n => ExprFactory.Product(ExprFactory.Variable(n), ExprFactory.Variable(n))));
        return scale == Rational.One ? sum : ExprFactory.Product(ExprFactory.Constant(scale), sum);
    }

    private static int OperationCost(Expr e) =>
        new CodeBlock([new AssignmentStatement("x", e, true)], new Dictionary<string, string>(), new Dictionary<string, string>()).Statistics().Cost;
}
