namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// One division where a block divides both by √x and by x: with q = 1/x, y/√x becomes y·√q and
/// z/x becomes z·q. Normalizing an axis and projecting onto it (k = a/|a|, then (a·u)/|a|²) is
/// the usual source. Kept only when the weighted cost falls and no operation is added.
/// </summary>
public sealed class SquareRootReciprocalPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public SquareRootReciprocalPass() : this(i => $"rsq{i}") { }

    public string Name => "square-root reciprocal";

    public CodeBlock Run(CodeBlock block)
    {
        var underRoot = new HashSet<Expr>();
        var divisors = new HashSet<Expr>();
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
        {
            if (node is not QuotientExpr q) continue;
            if (q.Denominator is CallExpr { Function: "sqrt" } root) underRoot.Add(root.Children[0]);
            else if (q.Denominator is not ConstantExpr) divisors.Add(q.Denominator);
        }
        foreach (var x in underRoot.Where(divisors.Contains).OrderBy(x => x.ToString(), StringComparer.Ordinal))
        {
            var candidate = Share(block, x);
            var (before, after) = (block.Statistics(), candidate.Statistics());
            if (after.Cost < before.Cost && after.Operations <= before.Operations) block = candidate;
        }
        return block;
    }

    private CodeBlock Share(CodeBlock block, Expr x)
    {
        var taken = new HashSet<string>(block.Statements.OfType<AssignmentStatement>().Select(a => a.Target), StringComparer.Ordinal);
        string name;
        do name = temporaryName(_counter++); while (!taken.Add(name));
        var reciprocal = ExprFactory.Variable(name);
        var result = new List<CodeStatement>();
        var inserted = false;
        foreach (var s in block.Statements)
        {
            var rewritten = BlockRewriting.MapExpressions(block.WithStatements([s]), e => BlockRewriting.ReplaceNodes(e, node => node switch
            {
                QuotientExpr { Denominator: CallExpr { Function: "sqrt" } root } q when root.Children[0].Equals(x) =>
                    ExprFactory.Product(q.Numerator, ExprFactory.Call("sqrt", reciprocal)),
                QuotientExpr q when q.Denominator.Equals(x) => ExprFactory.Product(q.Numerator, reciprocal),
                _ => null,
            })).Statements[0];
            if (!inserted && !ReferenceEquals(rewritten, s))
            {
                result.Add(new AssignmentStatement(name, ExprFactory.Quotient(ConstantExpr.One, x), false));
                inserted = true;
            }
            result.Add(rewritten);
        }
        return block.WithStatements(result);
    }
}
