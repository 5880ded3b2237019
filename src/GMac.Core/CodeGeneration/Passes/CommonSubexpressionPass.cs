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

    public CodeBlock Run(CodeBlock block) => Run(block, out _);

    /// <param name="counts">The counts as kept up to date through the extractions (for tests: they must equal a recount of the result).</param>
    internal CodeBlock Run(CodeBlock block, out KeyCounts counts)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        taken.UnionWith(block.InputText.Keys);
        counts = new KeyCounts();
        var statements = block.Statements.Select(s => Counted(s)).ToList();
        foreach (var c in statements) counts.Add(c.Keys, +1);
        for (var iteration = 0; iteration < 100_000; iteration++)
        {
            var best = FindBest(statements, counts);
            if (best is null) break;
            string name;
            do name = temporaryName(_counter++); while (!taken.Add(name));
            Extract(statements, counts, best, name);
        }
        return block.WithStatements(statements.Select(c => c.Statement));
    }

    /// <summary>A statement with its keys: count and first position (in <see cref="Expr.DescendantsAndSelf"/> order) of each.</summary>
    internal sealed record CountedStatement(CodeStatement Statement, Dictionary<Expr, (int Count, int First)> Keys);

    /// <summary>Occurrences of every key over the block, and the keys that occur more than once.</summary>
    internal sealed class KeyCounts
    {
        public Dictionary<Expr, int> Totals { get; } = new();

        public HashSet<Expr> Repeated { get; } = new();

        public void Add(Dictionary<Expr, (int Count, int First)> keys, int sign)
        {
            foreach (var (key, (count, _)) in keys)
            {
                var total = Totals.GetValueOrDefault(key) + sign * count;
                if (total == 0) Totals.Remove(key);
                else Totals[key] = total;
                if (total >= 2) Repeated.Add(key);
                else Repeated.Remove(key);
            }
        }
    }

    internal CountedStatement Counted(CodeStatement s)
    {
        var keys = new Dictionary<Expr, (int Count, int First)>();
        var position = 0;
        foreach (var root in s.Expressions)
        foreach (var node in root.DescendantsAndSelf())
        {
            if (node.IsLeaf || node is NegateExpr) continue;
            var key = Canonical(node).Key;
            if (key.IsLeaf) continue;
            keys[key] = keys.TryGetValue(key, out var known) ? (known.Count + 1, known.First) : (1, position++);
        }
        return new CountedStatement(s, keys);
    }

    /// <summary>
    /// The key that saves most; among equal savings the largest, then the one met first reading the
    /// statements in order. Counts are kept up to date per statement as extractions touch them, so
    /// a round reads only the keys that repeat, not the whole block.
    /// </summary>
    private Expr? FindBest(List<CountedStatement> statements, KeyCounts counts)
    {
        var bestSaving = 0;
        var bestSize = 0;
        var tied = new List<Expr>();
        foreach (var e in counts.Repeated)
        {
            var saving = (counts.Totals[e] - 1) * OperationCost(e);
            if (saving <= 0 || saving < bestSaving || (saving == bestSaving && e.Size < bestSize)) continue;
            if (saving > bestSaving || e.Size > bestSize) tied.Clear();
            bestSaving = saving;
            bestSize = e.Size;
            tied.Add(e);
        }
        if (tied.Count <= 1) return tied.FirstOrDefault();
        foreach (var c in statements)
        {
            Expr? first = null;
            var firstPosition = int.MaxValue;
            foreach (var e in tied)
                if (c.Keys.TryGetValue(e, out var at) && at.First < firstPosition)
                {
                    first = e;
                    firstPosition = at.First;
                }
            if (first is not null) return first;
        }
        return tied[0];
    }

    private readonly Dictionary<Expr, Expr> _keys = new(ReferenceEqualityComparer.Instance);

    /// <summary>The node with sums and products in a fixed order, so a·b and b·a share one key.</summary>
    private Expr Key(Expr e)
    {
        if (e.IsLeaf) return e;
        if (_keys.TryGetValue(e, out var key)) return key;
        var source = e.Children;
        var children = new Expr[source.Count];
        for (var i = 0; i < children.Length; i++) children[i] = Key(source[i]);
        if (e is SumExpr or ProductExpr)
            Array.Sort(children, ExprOrder.Compare);
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
        var terms = e.Children;
        var opposites = new Expr[terms.Count];
        for (var i = 0; i < opposites.Length; i++) opposites[i] = ExprFactory.Negate(terms[i]);
        var opposite = Key(ExprFactory.Sum(opposites));
        var oppositeFirst = ExprOrder.Compare(opposite, key) < 0;
        return oppositeFirst ? (opposite, true) : (key, false);
    }

    private readonly Dictionary<Expr, int> _costs = new();

    private int OperationCost(Expr e)
    {
        if (_costs.TryGetValue(e, out var known)) return known;
        return _costs[e] = ComputeCost(e);
    }

    private static int ComputeCost(Expr e) => CodeStatistics.CostOf(e);

    /// <summary>Names the key before its first use and replaces it (or its negation) in the statements that read it; only those are recounted.</summary>
    private void Extract(List<CountedStatement> statements, KeyCounts counts, Expr key, string name)
    {
        var variable = ExprFactory.Variable(name);
        bool Matches(Expr node) => !node.IsLeaf && node is not NegateExpr && Canonical(node).Key.Equals(key);
        Expr Replace(Expr root) => BlockRewriting.ReplaceNodes(root, node =>
            Matches(node) ? (Canonical(node).Negated ? ExprFactory.Negate(variable) : variable) : null);

        var firstUse = -1;
        for (var i = 0; i < statements.Count; i++)
        {
            var c = statements[i];
            if (!c.Keys.ContainsKey(key)) continue;
            if (firstUse < 0) firstUse = i;
            var s = c.Statement;
            var exprs = s.Expressions.Select(Replace).ToArray();
            if (exprs.SequenceEqual(s.Expressions, ReferenceEqualityComparer.Instance)) continue;
            counts.Add(c.Keys, -1);
            statements[i] = Counted(s.WithExpressions(exprs));
            counts.Add(statements[i].Keys, +1);
        }
        var definition = Counted(new AssignmentStatement(name, key, false));
        statements.Insert(firstUse, definition);
        counts.Add(definition.Keys, +1);
    }
}
