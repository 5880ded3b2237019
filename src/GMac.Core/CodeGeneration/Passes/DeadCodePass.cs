namespace GMac.Core.CodeGeneration.Passes;

/// <summary>Removes temporaries that no output or verbatim statement depends on.</summary>
public sealed class DeadCodePass : IOptimizerPass
{
    public string Name => "dead-code elimination";

    public CodeBlock Run(CodeBlock block)
    {
        var live = new HashSet<string>(StringComparer.Ordinal);
        var kept = new List<CodeStatement>();
        for (var i = block.Statements.Count - 1; i >= 0; i--)
        {
            var s = block.Statements[i];
            if (s is AssignmentStatement { IsOutput: false } temp && !live.Contains(temp.Target)) continue;
            kept.Add(s);
            foreach (var e in s.Expressions)
            foreach (var node in e.DescendantsAndSelf())
                if (node is VariableExpr v) live.Add(v.Name);
        }
        kept.Reverse();
        return kept.Count == block.Statements.Count ? block : block.WithStatements(kept);
    }
}
