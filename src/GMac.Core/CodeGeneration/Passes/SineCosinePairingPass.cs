namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Gives the sine and the cosine of one argument a temporary each when both occur in a block, so the
/// emitter can compute them together (C#'s <c>Math.SinCos</c>, one range reduction). The passes
/// before it leave a call inside a larger expression when it is read once, as in
/// <c>-cos ψ · sin λ</c>, which the emitter could not pair. Operation counts do not change.
/// </summary>
public sealed class SineCosinePairingPass(Func<int, string> temporaryName) : IOptimizerPass
{
    private int _counter;

    public SineCosinePairingPass() : this(i => $"trig{i}") { }

    public string Name => "sine-cosine pairing";

    public CodeBlock Run(CodeBlock block)
    {
        var sines = new HashSet<Expr>();
        var cosines = new HashSet<Expr>();
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
        {
            if (node is CallExpr { Function: "sin", Children: [var x] }) sines.Add(x);
            else if (node is CallExpr { Function: "cos", Children: [var y] }) cosines.Add(y);
        }
        var changed = false;
        foreach (var x in sines.Where(cosines.Contains).OrderBy(x => x.ToString(), StringComparer.Ordinal))
        {
            block = OwnTemporary(OwnTemporary(block, "sin", x, ref changed), "cos", x, ref changed);
        }
        return changed ? new CopyPropagationPass().Run(block) : block;
    }

    /// <summary>
    /// Makes f(x) the whole value of one temporary, read everywhere else. A temporary that already is
    /// f(x), assigned once and before any other use, is kept; otherwise a new one goes just before the
    /// first statement that uses f(x).
    /// </summary>
    private CodeBlock OwnTemporary(CodeBlock block, string function, Expr x, ref bool changed)
    {
        var call = ExprFactory.Call(function, x);
        var statements = block.Statements;
        var first = -1;
        for (var i = 0; i < statements.Count && first < 0; i++)
            if (statements[i].Expressions.Any(e => e.DescendantsAndSelf().Any(call.Equals)))
                first = i;
        if (first < 0) return block;

        var targets = statements.OfType<AssignmentStatement>().GroupBy(a => a.Target, StringComparer.Ordinal)
            .ToDictionary(g => g.Key, g => g.Count(), StringComparer.Ordinal);
        string name;
        var reuse = statements[first] is AssignmentStatement { IsOutput: false } existing && existing.Value.Equals(call) && targets[existing.Target] == 1;
        if (reuse)
        {
            name = ((AssignmentStatement)statements[first]).Target;
            if (!statements.Skip(first + 1).Any(s => s.Expressions.Any(e => e.DescendantsAndSelf().Any(call.Equals))))
                return block;
        }
        else
        {
            do name = temporaryName(_counter++); while (targets.ContainsKey(name));
        }

        var variable = ExprFactory.Variable(name);
        var result = new List<CodeStatement>(statements.Count + 1);
        for (var i = 0; i < statements.Count; i++)
        {
            if (i == first && !reuse) result.Add(new AssignmentStatement(name, call, false));
            var s = statements[i];
            if (i == first && reuse)
            {
                result.Add(s);
                continue;
            }
            var exprs = s.Expressions.Select(e => BlockRewriting.ReplaceNodes(e, node => node.Equals(call) ? variable : null)).ToArray();
            result.Add(exprs.Where((e, k) => !ReferenceEquals(e, s.Expressions[k])).Any() ? s.WithExpressions(exprs) : s);
        }
        changed = true;
        return block.WithStatements(result);
    }
}
