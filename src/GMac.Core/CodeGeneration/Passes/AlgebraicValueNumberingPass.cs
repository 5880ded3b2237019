using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Value numbering modulo algebra: each temporary is expanded into the inputs as a canonical
/// symbolic scalar (divisions cancelled), and a temporary whose value equals an earlier one, or
/// its negation, or a constant, is replaced by it. Common-subexpression elimination compares
/// trees; this compares values, so v₁ ∧ ((v₂ ∧ v₁) v₁⁻¹), computed from the rejection's
/// temporaries, is found to be −(v₂ ∧ v₁), already computed. Expansions that grow past a few
/// dozen terms are not followed (the temporary then takes part in no comparison).
/// </summary>
public sealed class AlgebraicValueNumberingPass : IOptimizerPass
{
    private const int MaxTerms = 48;

    public string Name => "algebraic value numbering";

    public CodeBlock Run(CodeBlock block)
    {
        var values = new Dictionary<string, Scalar?>(StringComparer.Ordinal);
        var byValue = new Dictionary<Scalar, string>();
        var replacements = new Dictionary<string, Expr>(StringComparer.Ordinal);
        var result = new List<CodeStatement>();
        foreach (var statement in block.Statements)
        {
            var s = ReplaceKnownSums(BlockRewriting.Substitute(statement, replacements), values, byValue);
            if (s is not AssignmentStatement { IsOutput: false } temp)
            {
                result.Add(s);
                continue;
            }
            var value = Expand(temp.Value, values);
            if (value is not null) value = InverseCancellation.CancelDeep(value);
            values[temp.Target] = value;
            if (value is null) { result.Add(s); continue; }
            if (value.TryGetConstant(out var constant))
            {
                replacements[temp.Target] = ExprFactory.Constant(constant);
                continue;
            }
            if (byValue.TryGetValue(value, out var same))
            {
                replacements[temp.Target] = ExprFactory.Variable(same);
                continue;
            }
            if (byValue.TryGetValue(-value, out var opposite))
            {
                replacements[temp.Target] = ExprFactory.Negate(ExprFactory.Variable(opposite));
                continue;
            }
            byValue[value] = temp.Target;
            result.Add(s);
        }
        return replacements.Count == 0 ? block : block.WithStatements(result);
    }

    /// <summary>Sums inside a statement whose value an earlier temporary holds (or its negation) read that temporary.</summary>
    private static CodeStatement ReplaceKnownSums(CodeStatement s, IReadOnlyDictionary<string, Scalar?> values, IReadOnlyDictionary<Scalar, string> byValue)
    {
        if (byValue.Count == 0) return s;
        var changed = false;
        var exprs = s.Expressions.Select(e =>
        {
            var r = BlockRewriting.ReplaceNodes(e, node =>
            {
                if (node is not SumExpr || ReferenceEquals(node, e) && s is AssignmentStatement { IsOutput: false }) return null;
                if (Expand(node, values) is not { } v) return null;
                v = InverseCancellation.CancelDeep(v);
                if (byValue.TryGetValue(v, out var same)) return ExprFactory.Variable(same);
                return byValue.TryGetValue(-v, out var opposite) ? ExprFactory.Negate(ExprFactory.Variable(opposite)) : null;
            });
            changed |= !ReferenceEquals(r, e);
            return r;
        }).ToArray();
        return changed ? s.WithExpressions(exprs) : s;
    }

    /// <summary>The canonical value of an expression over the inputs, or null when it is too large or not exact.</summary>
    private static Scalar? Expand(Expr e, IReadOnlyDictionary<string, Scalar?> temporaries)
    {
        Scalar? Go(Expr x)
        {
            switch (x)
            {
                case VariableExpr v:
                    return temporaries.TryGetValue(v.Name, out var t) ? t : Scalar.Variable(v.Name);
                case ConstantExpr c:
                    return c.Exact is { } r ? Scalar.Constant(r) : null;
                case NegateExpr n:
                    return Go(n.Operand) is { } o ? -o : null;
                case SumExpr s:
                {
                    var total = Scalar.Zero;
                    foreach (var child in s.Children)
                    {
                        if (Go(child) is not { } term) return null;
                        total += term;
                    }
                    return Small(total);
                }
                case ProductExpr p:
                {
                    var product = Scalar.One;
                    foreach (var child in p.Children)
                    {
                        if (Go(child) is not { } factor || (long)factor.Terms.Count * product.Terms.Count > 4 * MaxTerms) return null;
                        product *= factor;
                    }
                    return Small(product);
                }
                case QuotientExpr q:
                    return Go(q.Numerator) is { } num && Go(q.Denominator) is { } den && !Scalar.IsZero(den) ? Small(num * Scalar.Reciprocal(den)) : null;
                case PowerExpr pw:
                    return Go(pw.Base) is { } b && (b.Terms.Count == 1 || Math.Abs(pw.Exponent) <= 2) && !(Scalar.IsZero(b) && pw.Exponent < 0)
                        ? Small(Scalar.IntegerPower(b, pw.Exponent)) : null;
                case CallExpr call:
                {
                    var args = new Scalar[call.Children.Count];
                    for (var i = 0; i < args.Length; i++)
                        if (Go(call.Children[i]) is { } a) args[i] = a; else return null;
                    return (call.Function, args.Length) switch
                    {
                        ("sin", 1) => Scalar.Sin(args[0]),
                        ("cos", 1) => Scalar.Cos(args[0]),
                        ("tan", 1) => Scalar.Tan(args[0]),
                        ("acos", 1) => Scalar.Acos(args[0]),
                        ("sqrt", 1) => Scalar.Sqrt(args[0]),
                        ("exp", 1) => Scalar.Exp(args[0]),
                        ("log", 1) => Scalar.Log(args[0]),
                        ("abs", 1) => Scalar.Abs(args[0]),
                        ("sinh", 1) => Scalar.HyperbolicSine(args[0]),
                        ("cosh", 1) => Scalar.HyperbolicCosine(args[0]),
                        ("atan2", 2) => Scalar.Atan2(args[0], args[1]),
                        _ => null,
                    };
                }
                default:
                    return null;
            }
        }
        return Go(e);
    }

    private static Scalar? Small(Scalar s) => s.Terms.Count > MaxTerms ? null : s;
}
