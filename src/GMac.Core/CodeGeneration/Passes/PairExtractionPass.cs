using System.Runtime.CompilerServices;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Common subexpressions hidden inside flattened products and sums: when two factors occur
/// together in several products (a·b·c and a·b·d), or two terms in several sums, their product
/// or sum becomes a temporary. The pair found in most nodes goes first, until no pair repeats.
/// </summary>
public sealed class PairExtractionPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public string Name => "shared factor and term pairs";

    public PairExtractionPass() : this(i => $"pair{i}") { }

    internal readonly record struct Pair(Expr First, Expr Second);

    public CodeBlock Run(CodeBlock block)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        taken.UnionWith(block.InputText.Keys);
        for (var iteration = 0; iteration < 10_000; iteration++)
        {
            var chosen = FindBest(block);
            if (chosen.Count == 0) return block;
            foreach (var (pair, isProduct) in chosen)
            {
                string name;
                do name = temporaryName(_counter++); while (!taken.Add(name));
                block = Extract(block, pair, isProduct, name);
            }
        }
        return block;
    }

    /// <summary>Pairs extracted per count of the block: their items are disjoint, so extracting one leaves the others' counts intact.</summary>
    private const int PairsPerRound = 16;

    /// <summary>Terms of a sum as (operand, negated); factors of a product as (factor, false).</summary>
    private static List<(Expr Item, bool Negated)> Items(Expr node) =>
        node is SumExpr
            ? node.Children.Select(c => c is NegateExpr n ? (n.Operand, true) : (c, false)).ToList()
            : node.Children.Select(c => (c, false)).ToList();

    /// <summary>
    /// The pair of two items in a fixed orientation: ordered by a deterministic key, and for sums
    /// with the first term positive (−a − b is −(a + b)); reports whether the occurrence is negated.
    /// </summary>
    private static (Pair Pair, bool Negated) Orient((Expr Item, bool Negated) x, (Expr Item, bool Negated) y, bool isProduct)
    {
        if (Order(y.Item, x.Item) < 0) (x, y) = (y, x);
        if (isProduct) return (new Pair(x.Item, y.Item), false);
        var negated = x.Negated;
        var second = negated ? !y.Negated : y.Negated;
        return (new Pair(x.Item, second ? ExprFactory.Negate(y.Item) : y.Item), negated);
    }

    private static int Order(Expr a, Expr b) => ExprOrder.Compare(a, b);

    /// <summary>Nodes with more items than this are not searched for pairs (the count grows quadratically).</summary>
    private const int MaxItems = 12;

    /// <summary>
    /// The pairs of one statement in the order they are first met, each with the number of its
    /// nodes that hold it. A statement is immutable and an extraction rebuilds only the statements
    /// it touches, so the others keep their lists from one count of the block to the next.
    /// </summary>
    private readonly ConditionalWeakTable<CodeStatement, List<((Pair, bool) Key, int Count)>> _statementPairs = new();

    private List<((Pair, bool) Key, int Count)> PairsOf(CodeStatement statement) =>
        _statementPairs.GetValue(statement, CountPairs);

    private static List<((Pair, bool) Key, int Count)> CountPairs(CodeStatement statement)
    {
        var counts = new Dictionary<(Pair, bool), int>();
        var order = new List<(Pair, bool)>();
        var items = new List<(Expr Item, bool Negated)>(MaxItems);
        var seen = new HashSet<(Pair, bool)>();
        var pending = new Stack<Expr>();
        foreach (var root in statement.Expressions)
        {
            pending.Push(root);
            while (pending.Count > 0)
            {
                var node = pending.Pop();
                var children = node.Children;
                for (var c = 0; c < children.Count; c++) pending.Push(children[c]);
                if (node is not (SumExpr or ProductExpr) || children.Count > MaxItems) continue;
                var isProduct = node is ProductExpr;
                items.Clear();
                foreach (var child in children)
                    items.Add(!isProduct && child is NegateExpr n ? (n.Operand, true) : (child, false));
                seen.Clear();
                for (var i = 0; i < items.Count; i++)
                for (var j = i + 1; j < items.Count; j++)
                {
                    var key = (Orient(items[i], items[j], isProduct).Pair, isProduct);
                    if (!seen.Add(key)) continue;
                    if (counts.TryGetValue(key, out var count)) counts[key] = count + 1;
                    else { counts[key] = 1; order.Add(key); }
                }
            }
        }
        return order.Select(k => (k, counts[k])).ToList();
    }

    internal List<(Pair Pair, bool IsProduct)> FindBest(CodeBlock block)
    {
        // The statements' lists merged in statement order: the same counts and first-seen order as
        // one walk over the whole block, without walking the statements no extraction changed.
        var counts = new Dictionary<(Pair, bool), int>();
        var order = new List<(Pair, bool)>();
        foreach (var s in block.Statements)
        foreach (var (key, n) in PairsOf(s))
        {
            if (counts.TryGetValue(key, out var count)) counts[key] = count + n;
            else { counts[key] = n; order.Add(key); }
        }
        // Most shared first (stable: first seen first); then greedily those that share no item.
        var ranked = order.Where(k => counts[k] >= 2).OrderByDescending(k => counts[k]).ToList();
        var used = new HashSet<Expr>();
        var chosen = new List<(Pair, bool)>();
        foreach (var key in ranked)
        {
            var (pair, _) = key;
            var second = pair.Second is NegateExpr n ? n.Operand : pair.Second;
            if (used.Contains(pair.First) || used.Contains(second)) continue;
            used.Add(pair.First);
            used.Add(second);
            chosen.Add(key);
            if (chosen.Count == PairsPerRound) break;
        }
        return chosen;
    }

    private static CodeBlock Extract(CodeBlock block, Pair pair, bool isProduct, string name)
    {
        var variable = ExprFactory.Variable(name);
        var value = isProduct ? ExprFactory.Product(pair.First, pair.Second) : ExprFactory.Sum(pair.First, pair.Second);

        Expr? Rewrite(Expr node)
        {
            if (isProduct ? node is not ProductExpr : node is not SumExpr) return null;
            var items = Items(node);
            for (var i = 0; i < items.Count; i++)
            for (var j = i + 1; j < items.Count; j++)
            {
                var (p, negated) = Orient(items[i], items[j], isProduct);
                if (!p.Equals(pair)) continue;
                var rest = node.Children.Where((_, k) => k != i && k != j).ToList();
                if (isProduct) return ExprFactory.Product(rest.Append(variable));
                return ExprFactory.Sum(rest.Append(negated ? ExprFactory.Negate(variable) : variable));
            }
            return null;
        }

        var result = new List<CodeStatement>();
        var inserted = false;
        foreach (var s in block.Statements)
        {
            var exprs = s.Expressions.Select(e => BlockRewriting.ReplaceNodes(e, Rewrite)).ToArray();
            var changed = !exprs.SequenceEqual(s.Expressions, ReferenceEqualityComparer.Instance);
            if (!inserted && changed)
            {
                result.Add(new AssignmentStatement(name, value, false));
                inserted = true;
            }
            result.Add(changed ? s.WithExpressions(exprs) : s);
        }
        return block.WithStatements(result);
    }
}
