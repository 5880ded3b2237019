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
        var samples = Samples(block);
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
    private sealed record CandidateSet(string[] Names, double First, double Second);

    private static bool Usable(double x) => double.IsFinite(x) && x != 0;

    /// <summary>c·Σ t² for the first set whose sum of squares the node equals exactly, when that costs less.</summary>
    private static Expr? Match(SumExpr node, int index, List<CandidateSet> sets, Dictionary<string, int> position, Dictionary<string, (double, double)> samples, PolynomialValues values)
    {
        var (first, second) = Evaluate(node, samples);
        if (!Usable(first) || !Usable(second)) return null;
        Scalar? p = null;
        int? nodeCost = null;
        foreach (var set in sets)
        {
            var ratio = first / set.First;
            if (Math.Abs(second / set.Second - ratio) > 1e-9 * Math.Abs(ratio)) continue;
            if (set.Names.Any(n => position[n] >= index)) continue;
            // the cost test comes before any expansion: most numeric matches are the squares already written out
            var squaresCost = 2 * set.Names.Length - 1 + (Math.Abs(Math.Abs(ratio) - 1) < 1e-9 ? 0 : 1);
            if (squaresCost >= (nodeCost ??= OperationCost(node))) continue;
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
    private static List<CandidateSet> CandidateSets(CodeBlock block, Dictionary<string, int> position, Dictionary<string, (double First, double Second)> samples)
    {
        var seen = new HashSet<string>(StringComparer.Ordinal);
        var sets = new List<CandidateSet>();
        // the temporaries a node reads (null past the largest set tried); sums and whole expressions record theirs
        string[]? Visit(Expr node, bool top)
        {
            string[]? names;
            if (node is VariableExpr v) names = position.ContainsKey(v.Name) ? [v.Name] : [];
            else if (node.IsLeaf) names = [];
            else
            {
                names = [];
                foreach (var c in node.Children)
                {
                    var inner = Visit(c, false);
                    names = names is null || inner is null ? null : Union(names, inner);
                }
            }
            if (names is null || names.Length < 2 || node is not SumExpr && !top || !seen.Add(string.Join(",", names))) return names;
            double first = 0, second = 0;
            foreach (var n in names)
            {
                var (x, y) = samples[n];
                first += x * x;
                second += y * y;
            }
            if (Usable(first) && Usable(second)) sets.Add(new CandidateSet(names, first, second));
            return names;
        }
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
            Visit(e, true);
        return sets;
    }

    /// <summary>The sorted union of two sorted name lists, null past the largest set tried.</summary>
    private static string[]? Union(string[] a, string[] b)
    {
        if (b.Length == 0 || ReferenceEquals(a, b)) return a;
        if (a.Length == 0) return b;
        var merged = a.Union(b, StringComparer.Ordinal).Order(StringComparer.Ordinal).ToArray();
        return merged.Length > MaxSetSize ? null : merged;
    }

    /// <summary>
    /// Every name of the block at two pseudo-random points (inputs in [0.5, 2]). Two samples rule
    /// out almost every (sum, set) pair before any polynomial is expanded.
    /// </summary>
    private static Dictionary<string, (double First, double Second)> Samples(CodeBlock block)
    {
        var (first, second) = (new Random(1), new Random(2));
        var values = new Dictionary<string, (double, double)>(StringComparer.Ordinal);
        foreach (var input in block.InputText.Keys.Order(StringComparer.Ordinal))
            values[input] = (0.5 + 1.5 * first.NextDouble(), 0.5 + 1.5 * second.NextDouble());
        foreach (var a in block.Statements.OfType<AssignmentStatement>())
            values[a.Target] = Evaluate(a.Value, values);
        return values;
    }

    /// <summary>An expression at both samples at once; NaN for a name or function without a value.</summary>
    private static (double First, double Second) Evaluate(Expr e, Dictionary<string, (double First, double Second)> values)
    {
        switch (e)
        {
            case ConstantExpr c: return (c.Value, c.Value);
            case VariableExpr v: return values.TryGetValue(v.Name, out var known) ? known : (double.NaN, double.NaN);
            case SumExpr:
            {
                double x = 0, y = 0;
                foreach (var c in e.Children)
                {
                    var (cx, cy) = Evaluate(c, values);
                    (x, y) = (x + cx, y + cy);
                }
                return (x, y);
            }
            case ProductExpr:
            {
                double x = 1, y = 1;
                foreach (var c in e.Children)
                {
                    var (cx, cy) = Evaluate(c, values);
                    (x, y) = (x * cx, y * cy);
                }
                return (x, y);
            }
            case NegateExpr n:
            {
                var (x, y) = Evaluate(n.Operand, values);
                return (-x, -y);
            }
            case QuotientExpr q:
            {
                var (nx, ny) = Evaluate(q.Numerator, values);
                var (dx, dy) = Evaluate(q.Denominator, values);
                return (nx / dx, ny / dy);
            }
            case PowerExpr p:
            {
                var (x, y) = Evaluate(p.Base, values);
                return (Math.Pow(x, p.Exponent), Math.Pow(y, p.Exponent));
            }
            case CallExpr call:
            {
                var args = call.Children.Select(c => Evaluate(c, values)).ToArray();
                var fx = MathFunctions.TryEvaluate(call.Function, args.Select(a => a.First).ToArray(), out var rx) ? rx : double.NaN;
                var fy = MathFunctions.TryEvaluate(call.Function, args.Select(a => a.Second).ToArray(), out var ry) ? ry : double.NaN;
                return (fx, fy);
            }
            default: return (double.NaN, double.NaN);
        }
    }

    private static Expr Squares(IEnumerable<string> names, Rational scale)
    {
        var sum = ExprFactory.Sum(names.Select(n => ExprFactory.Product(ExprFactory.Variable(n), ExprFactory.Variable(n))));
        return scale == Rational.One ? sum : ExprFactory.Product(ExprFactory.Constant(scale), sum);
    }

    private static int OperationCost(Expr e) => CodeStatistics.CostOf(e);
}
