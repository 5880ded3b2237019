namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// The other side of <see cref="StrengthReductionPass"/>: every product with a reciprocal
/// r = 1/d becomes a division by d (r's statement then holds d). One division and a
/// multiplication per use is cheaper where the divider is idle and the multipliers are the busy
/// units: the closest points of two skew lines divide two numerators by |n|² in 21
/// multiplications and 2 divisions instead of 23 and 1, and each quotient is rounded once instead
/// of twice. Which of the two forms is faster is the time model's call; the generator offers this
/// one as another candidate.
/// </summary>
public sealed class ReciprocalDivisionPass : IOptimizerPass
{
    public string Name => "reciprocals as divisions";

    public CodeBlock Run(CodeBlock block)
    {
        if (block.Statements.Any(s => s is VerbatimStatement)) return block;
        var assigned = block.Temporaries.GroupBy(t => t.Target, StringComparer.Ordinal).Where(g => g.Count() == 1).Select(g => g.Key).ToHashSet(StringComparer.Ordinal);
        var reciprocals = block.Temporaries
            .Where(t => assigned.Contains(t.Target) && t.Value is QuotientExpr { Numerator: ConstantExpr { Value: 1 } })
            .Select(t => t.Target).ToHashSet(StringComparer.Ordinal);
        if (reciprocals.Count == 0) return block;
        // What each reciprocal's products are divided by: its denominator where that is a name
        // already (1/x: no statement is left), else the reciprocal's own name, which now holds d.
        // A name assigned more than once may hold another value where r is used: r keeps its statement.
        var reassigned = block.Statements.OfType<AssignmentStatement>().GroupBy(a => a.Target, StringComparer.Ordinal)
            .Where(g => g.Count() > 1).Select(g => g.Key).ToHashSet(StringComparer.Ordinal);
        var divisors = new Dictionary<string, Expr>(StringComparer.Ordinal);
        foreach (var t in block.Temporaries.Where(t => reciprocals.Contains(t.Target)))
            divisors[t.Target] = ((QuotientExpr)t.Value).Denominator is VariableExpr v && !reciprocals.Contains(v.Name) && !reassigned.Contains(v.Name)
                ? v : ExprFactory.Variable(t.Target);
        var statements = new List<CodeStatement>(block.Statements.Count);
        foreach (var s in block.Statements.Cast<AssignmentStatement>())
        {
            if (reciprocals.Contains(s.Target))
            {
                if (divisors[s.Target] is VariableExpr d && d.Name != s.Target) continue;
                if (Divided(((QuotientExpr)s.Value).Denominator, reciprocals, divisors) is not { } denominator) return block;
                statements.Add(s with { Value = denominator });
                continue;
            }
            if (Divided(s.Value, reciprocals, divisors) is not { } value) return block;
            statements.Add(s with { Value = value });
        }
        return block.WithStatements(statements);
    }

    /// <summary>
    /// The value with each product r·x written x / d (d the divisor of r) and a bare r as 1/d;
    /// null where a product holds a reciprocal more than once or holds two of them.
    /// </summary>
    private static Expr? Divided(Expr e, HashSet<string> reciprocals, Dictionary<string, Expr> divisors)
    {
        switch (e)
        {
            case VariableExpr v when reciprocals.Contains(v.Name):
                return ExprFactory.Quotient(ConstantExpr.One, divisors[v.Name]);
            case ProductExpr p:
            {
                var inside = p.Children.Where(c => c is VariableExpr v && reciprocals.Contains(v.Name)).ToList();
                if (inside.Count > 1) return null;
                var others = new List<Expr>(p.Children.Count);
                foreach (var c in p.Children)
                {
                    if (inside.Count == 1 && ReferenceEquals(c, inside[0])) continue;
                    if (Divided(c, reciprocals, divisors) is not { } d) return null;
                    others.Add(d);
                }
                var rest = ExprFactory.Product(others);
                return inside.Count == 1 ? ExprFactory.Quotient(rest, divisors[((VariableExpr)inside[0]).Name]) : rest;
            }
            default:
            {
                if (e.IsLeaf) return e;
                var children = new Expr[e.Children.Count];
                var changed = false;
                for (var i = 0; i < children.Length; i++)
                {
                    if (Divided(e.Children[i], reciprocals, divisors) is not { } d) return null;
                    children[i] = d;
                    changed |= !ReferenceEquals(d, e.Children[i]);
                }
                return changed ? e.WithChildren(children) : e;
            }
        }
    }
}
