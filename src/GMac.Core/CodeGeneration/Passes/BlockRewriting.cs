namespace GMac.Core.CodeGeneration.Passes;

/// <summary>Shared helpers of the passes: use counts, dependencies and substitution of temporaries.</summary>
internal static class BlockRewriting
{
    /// <summary>How many times each variable is read, over all statements.</summary>
    public static Dictionary<string, int> UseCounts(IEnumerable<CodeStatement> statements)
    {
        var counts = new Dictionary<string, int>(StringComparer.Ordinal);
        foreach (var s in statements)
        foreach (var e in s.Expressions)
        foreach (var node in e.DescendantsAndSelf())
            if (node is VariableExpr v) counts[v.Name] = counts.GetValueOrDefault(v.Name) + 1;
        return counts;
    }

    /// <summary>
    /// The block's statements with, for each, the indices of the earlier statements it reads: what a
    /// pass that reorders statements may move. Null where the order itself carries meaning: a
    /// statement that is not an assignment, a name assigned twice, or a name read before its
    /// assignment (an input the assignment shadows).
    /// </summary>
    public static (AssignmentStatement[] Statements, int[][] Reads)? Dependencies(CodeBlock block)
    {
        if (block.Statements.Any(s => s is not AssignmentStatement)) return null;
        var statements = block.Statements.Cast<AssignmentStatement>().ToArray();
        var definedAt = new Dictionary<string, int>(StringComparer.Ordinal);
        for (var i = 0; i < statements.Length; i++)
            if (!definedAt.TryAdd(statements[i].Target, i)) return null;
        var reads = new int[statements.Length][];
        for (var i = 0; i < statements.Length; i++)
        {
            var read = new List<int>();
            foreach (var v in statements[i].Value.DescendantsAndSelf().OfType<VariableExpr>())
            {
                if (!definedAt.TryGetValue(v.Name, out var d)) continue;
                if (d >= i) return null;
                if (!read.Contains(d)) read.Add(d);
            }
            reads[i] = [.. read];
        }
        return (statements, reads);
    }

    /// <summary>Replaces the chosen temporaries by their values everywhere and removes their statements.</summary>
    public static CodeBlock InlineTemporaries(CodeBlock block, Func<AssignmentStatement, bool> shouldInline)
    {
        var replacements = new Dictionary<string, Expr>(StringComparer.Ordinal);
        var result = new List<CodeStatement>();
        foreach (var s in block.Statements)
        {
            var rewritten = Substitute(s, replacements);
            if (rewritten is AssignmentStatement { IsOutput: false } temp && shouldInline(temp))
            {
                replacements[temp.Target] = temp.Value;
                continue;
            }
            result.Add(rewritten);
        }
        return block.WithStatements(result);
    }

    public static CodeStatement Substitute(CodeStatement s, IReadOnlyDictionary<string, Expr> replacements)
    {
        if (replacements.Count == 0) return s;
        var changed = false;
        var exprs = s.Expressions.Select(e =>
        {
            var r = Substitute(e, replacements);
            changed |= !ReferenceEquals(r, e);
            return r;
        }).ToArray();
        return changed ? s.WithExpressions(exprs) : s;
    }

    public static Expr Substitute(Expr e, IReadOnlyDictionary<string, Expr> replacements) =>
        e.Rewrite(node => node switch
        {
            VariableExpr v when replacements.TryGetValue(v.Name, out var r) => r,
            _ when node.IsLeaf => node,
            _ => ExprFactory.Normalize(node),
        });

    /// <summary>
    /// Replaces the nodes for which <paramref name="replace"/> answers (outermost first); untouched
    /// subtrees keep their identity and only the parents of a replacement are renormalized.
    /// </summary>
    public static Expr ReplaceNodes(Expr node, Func<Expr, Expr?> replace)
    {
        if (replace(node) is { } replacement) return replacement;
        if (node.IsLeaf) return node;
        var children = node.Children;
        Expr[]? rebuilt = null;
        for (var i = 0; i < children.Count; i++)
        {
            var c = ReplaceNodes(children[i], replace);
            if (rebuilt is null && !ReferenceEquals(c, children[i]))
            {
                rebuilt = new Expr[children.Count];
                for (var j = 0; j < i; j++) rebuilt[j] = children[j];
            }
            if (rebuilt is not null) rebuilt[i] = c;
        }
        return rebuilt is null ? node : ExprFactory.Normalize(node.WithChildren(rebuilt));
    }

    /// <summary>Applies a rewrite to every expression of every statement.</summary>
    public static CodeBlock MapExpressions(CodeBlock block, Func<Expr, Expr> map) =>
        block.WithStatements(block.Statements.Select(s =>
        {
            var exprs = s.Expressions.Select(map).ToArray();
            return exprs.Where((e, i) => !ReferenceEquals(e, s.Expressions[i])).Any() ? s.WithExpressions(exprs) : s;
        }));
}
