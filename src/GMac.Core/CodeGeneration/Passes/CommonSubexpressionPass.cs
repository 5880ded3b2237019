namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Common-subexpression elimination across all statements: a subtree that occurs more than once
/// (or occurs once and once negated, as a − b and b − a) becomes a temporary, the one that saves
/// most operations first, until nothing repeats.
/// </summary>
public sealed class CommonSubexpressionPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public string Name => "common-subexpression elimination";

    public CommonSubexpressionPass() : this(i => $"cse{i}") { }

    public CodeBlock Run(CodeBlock block)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        taken.UnionWith(block.InputText.Keys);
        for (var iteration = 0; iteration < 100_000; iteration++)
        {
            var best = FindBest(block);
            if (best is null) return block;
            string name;
            do name = temporaryName(_counter++); while (!taken.Add(name));
            block = Extract(block, best, name);
        }
        return block;
    }

    private readonly Dictionary<Expr, Expr> _keys = new(ReferenceEqualityComparer.Instance);

    /// <summary>The node with sums and products in a fixed order, so a·b and b·a share one key.</summary>
    private Expr Key(Expr e)
    {
        if (e.IsLeaf) return e;
        if (_keys.TryGetValue(e, out var key)) return key;
        var children = e.Children.Select(Key).ToList();
        if (e is SumExpr or ProductExpr)
            children.Sort(ExprOrder.Compare);
        key = e.WithChildren(children);
        // Equal keys are made one object: their children are already shared, so this look-up compares
        // one level, and every later comparison of keys (counting, matching) stops at reference equality
        // instead of walking both subtrees.
        if (_interned.TryGetValue(key, out var shared)) key = shared;
        else _interned[key] = key;
        _keys[e] = key;
        return key;
    }

    private readonly Dictionary<Expr, Expr> _interned = new();

    /// <summary>The key shared by e and −e, and whether e is the negated one (a − b and b − a).</summary>
    private readonly Dictionary<Expr, (Expr, bool)> _canonical = new(ReferenceEqualityComparer.Instance);

    private (Expr Key, bool Negated) Canonical(Expr e)
    {
        if (_canonical.TryGetValue(e, out var known)) return known;
        return _canonical[e] = ComputeCanonical(e);
    }

    private (Expr Key, bool Negated) ComputeCanonical(Expr e)
    {
        if (e is NegateExpr n)
        {
            var (k, negated) = Canonical(n.Operand);
            return (k, !negated);
        }
        var key = Key(e);
        if (e is not SumExpr) return (key, false);
        var opposite = Key(ExprFactory.Sum(e.Children.Select(ExprFactory.Negate)));
        var oppositeFirst = ExprOrder.Compare(opposite, key) < 0;
        return oppositeFirst ? (opposite, true) : (key, false);
    }

    private Expr? FindBest(CodeBlock block)
    {
        var counts = new Dictionary<Expr, int>();
        foreach (var s in block.Statements)
        foreach (var root in s.Expressions)
        foreach (var node in root.DescendantsAndSelf())
        {
            if (node.IsLeaf || node is NegateExpr) continue;
            var key = Canonical(node).Key;
            if (key.IsLeaf) continue;
            counts[key] = counts.GetValueOrDefault(key) + 1;
        }
        Expr? best = null;
        var bestSaving = 0;
        foreach (var (e, count) in counts)
        {
            if (count < 2) continue;
            var saving = (count - 1) * OperationCost(e);
            if (saving > bestSaving || (saving == bestSaving && best is not null && e.Size > best.Size))
            {
                best = e;
                bestSaving = saving;
            }
        }
        return best;
    }

    private readonly Dictionary<Expr, int> _costs = new();

    private int OperationCost(Expr e)
    {
        if (_costs.TryGetValue(e, out var known)) return known;
        return _costs[e] = ComputeCost(e);
    }

    private static int ComputeCost(Expr e)
    {
        var block = new CodeBlock([new AssignmentStatement("x", e, true)], new Dictionary<string, string>(), new Dictionary<string, string>());
        return block.Statistics().Cost;
    }

    private CodeBlock Extract(CodeBlock block, Expr key, string name)
    {
        var variable = ExprFactory.Variable(name);
        bool Matches(Expr node) => !node.IsLeaf && node is not NegateExpr && Canonical(node).Key.Equals(key);
        Expr Replace(Expr root) => BlockRewriting.ReplaceNodes(root, node =>
            Matches(node) ? (Canonical(node).Negated ? ExprFactory.Negate(variable) : variable) : null);

        var result = new List<CodeStatement>();
        var inserted = false;
        foreach (var s in block.Statements)
        {
            if (!inserted && s.Expressions.Any(e => e.DescendantsAndSelf().Any(Matches)))
            {
                result.Add(new AssignmentStatement(name, key, false));
                inserted = true;
            }
            var exprs = s.Expressions.Select(Replace).ToArray();
            result.Add(exprs.SequenceEqual(s.Expressions, ReferenceEqualityComparer.Instance) ? s : s.WithExpressions(exprs));
        }
        return block.WithStatements(result);
    }
}
