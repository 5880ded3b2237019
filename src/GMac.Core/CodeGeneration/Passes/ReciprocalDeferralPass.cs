namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Multiplies by a reciprocal r = 1/d as late as possible. Temporaries of the form x·r that
/// only feed sums and products in which every term carries exactly one factor r are kept
/// unscaled, and each output that is linear in r is multiplied by r once at the end:
/// t1 = −a·r, t2 = −b·r, o = p·t1 + q·t2 becomes o = r·(−(p·a + q·b)). That saves the
/// multiplications of the scaled temporaries beyond one per output, and it takes the division
/// off the critical path: the numerators are computed while it is under way, as a hand
/// derivation does, instead of every later operation waiting for it. A rewrite is kept only
/// when it costs strictly less.
/// </summary>
public sealed class ReciprocalDeferralPass : IOptimizerPass
{
    public string Name => "deferred reciprocals";

    public CodeBlock Run(CodeBlock block)
    {
        if (block.Statements.Any(s => s is VerbatimStatement)) return block;
        var reciprocals = block.Temporaries
            .Where(t => t.Value is QuotientExpr { Numerator: ConstantExpr { Value: 1 } })
            .Select(t => t.Target).ToList();
        foreach (var r in reciprocals)
        {
            var deferred = Defer(block, r);
            if (deferred.Statistics().Cost < block.Statistics().Cost) block = deferred;
        }
        return block;
    }

    private static CodeBlock Defer(CodeBlock block, string r)
    {
        // names whose value carries one factor r: r itself (1·r) and the temporaries made unscaled
        var scaled = new HashSet<string>(StringComparer.Ordinal) { r };
        var reciprocal = ExprFactory.Variable(r);
        // unscaled temporaries stored with the opposite sign, so that −a − b costs no negation
        var flipped = new HashSet<string>(StringComparer.Ordinal);
        var statements = new List<CodeStatement>();
        var after = false;
        foreach (var original in block.Statements.Cast<AssignmentStatement>())
        {
            if (!after)
            {
                statements.Add(original);
                after = original.Target == r;
                continue;
            }
            var s = flipped.Count == 0 ? original : original with
            {
                Value = original.Value.Rewrite(n => n is VariableExpr v && flipped.Contains(v.Name) ? ExprFactory.Negate(v) : n),
            };
            switch (Degree(s.Value, scaled))
            {
                case 0:
                    statements.Add(s);
                    break;
                case 1 when !s.IsOutput:
                    var value = Strip(s.Value, scaled, r);
                    if (value is NegateExpr || value is SumExpr sum && sum.Children.All(t => t is NegateExpr))
                    {
                        value = value is SumExpr terms ? ExprFactory.Sum(terms.Children.Select(ExprFactory.Negate)) : ExprFactory.Negate(value);
                        flipped.Add(s.Target);
                    }
                    statements.Add(s with { Value = value });
                    scaled.Add(s.Target);
                    break;
                case 1:
                    statements.Add(s with { Value = ExprFactory.Product(reciprocal, Strip(s.Value, scaled, r)) });
                    break;
                default:
                    // anything else reads the unscaled temporaries times r, as they were
                    statements.Add(s with
                    {
                        Value = s.Value.Rewrite(n => n is VariableExpr v && v.Name != r && scaled.Contains(v.Name)
                            ? ExprFactory.Product(reciprocal, v)
                            : n),
                    });
                    break;
            }
        }
        var result = block.WithStatements(statements);
        return new DeadCodePass().Run(new CopyPropagationPass().Run(new ConstantFoldingPass().Run(result)));
    }

    /// <summary>How many factors r every term of the value carries; null when terms differ or r sits under a quotient, power or call.</summary>
    private static int? Degree(Expr e, IReadOnlySet<string> scaled)
    {
        switch (e)
        {
            case VariableExpr v:
                return scaled.Contains(v.Name) ? 1 : 0;
            case ConstantExpr:
                return 0;
            case NegateExpr n:
                return Degree(n.Operand, scaled);
            case SumExpr s:
            {
                int? degree = null;
                foreach (var t in s.Children)
                {
                    var d = Degree(t, scaled);
                    if (d is null || degree is { } known && known != d) return null;
                    degree = d;
                }
                return degree ?? 0;
            }
            case ProductExpr p:
            {
                var total = 0;
                foreach (var f in p.Children)
                {
                    if (Degree(f, scaled) is not { } d) return null;
                    total += d;
                }
                return total;
            }
            default:
                return e.Children.All(c => Degree(c, scaled) == 0) ? 0 : null;
        }
    }

    /// <summary>The value divided by r, for a value of degree one: one factor r leaves each term.</summary>
    private static Expr Strip(Expr e, IReadOnlySet<string> scaled, string r)
    {
        switch (e)
        {
            case VariableExpr v when v.Name == r:
                return ConstantExpr.One;
            case VariableExpr v:
                return v; // an unscaled temporary already holds its value divided by r
            case NegateExpr n:
                return ExprFactory.Negate(Strip(n.Operand, scaled, r));
            case SumExpr s:
                return ExprFactory.Sum(s.Children.Select(t => Strip(t, scaled, r)));
            case ProductExpr p:
            {
                var factors = p.Children.ToArray();
                var i = Array.FindIndex(factors, f => Degree(f, scaled) == 1);
                factors[i] = Strip(factors[i], scaled, r);
                return ExprFactory.Product(factors);
            }
            default:
                throw new InvalidOperationException($"no factor {r} to take out of {e}");
        }
    }
}
