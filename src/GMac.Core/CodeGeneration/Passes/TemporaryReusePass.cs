namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Renames temporaries to a small set of names, giving a name back once its value has been read
/// for the last time, so long blocks declare few locals. Run last: afterwards a name may be
/// assigned more than once.
/// </summary>
public sealed class TemporaryReusePass(Func<int, string> temporaryName) : IOptimizerPass
{
    public string Name => "temporary reuse";

    public TemporaryReusePass() : this(i => $"t{i}") { }

    public CodeBlock Run(CodeBlock block)
    {
        var temps = new HashSet<string>(block.Temporaries.Select(t => t.Target), StringComparer.Ordinal);
        var lastUse = new Dictionary<string, int>(StringComparer.Ordinal);
        for (var i = 0; i < block.Statements.Count; i++)
        foreach (var e in block.Statements[i].Expressions)
        foreach (var node in e.DescendantsAndSelf())
            if (node is VariableExpr v && temps.Contains(v.Name)) lastUse[v.Name] = i;

        var rename = new Dictionary<string, Expr>(StringComparer.Ordinal);
        var free = new SortedSet<int>();
        var next = 0;
        var reserved = new HashSet<string>(block.InputText.Keys, StringComparer.Ordinal);
        var result = new List<CodeStatement>();
        for (var i = 0; i < block.Statements.Count; i++)
        {
            var s = BlockRewriting.Substitute(block.Statements[i], rename);
            foreach (var (name, last) in lastUse)
                if (last == i && rename.TryGetValue(name, out var r) && r is VariableExpr rv) free.Add(IndexOf(rv.Name));
            if (s is AssignmentStatement { IsOutput: false } temp)
            {
                int index;
                if (free.Count > 0) { index = free.Min; free.Remove(index); }
                else
                {
                    do index = next++; while (reserved.Contains(temporaryName(index)));
                }
                _names[index] = temporaryName(index);
                rename[temp.Target] = ExprFactory.Variable(temporaryName(index));
                if (!lastUse.ContainsKey(temp.Target)) free.Add(index); // never read: its name is free at once
                s = temp with { Target = temporaryName(index) };
            }
            result.Add(s);
        }
        return block.WithStatements(result);

        int IndexOf(string name) => _names.First(kv => kv.Value == name).Key;
    }

    private readonly Dictionary<int, string> _names = new();
}
