using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// The values of a block's expressions as canonical polynomials, read through the temporaries
/// that are polynomials of earlier names; a temporary that is not (it divides or calls) stays a
/// variable of its own. Two expressions with the same value here are equal for
/// every input, so a rewrite may swap one for the other. Values past a few dozen terms are not
/// followed: comparing them would cost more than the rewrites that ask are worth.
/// </summary>
internal sealed class PolynomialValues
{
    public const int MaxTerms = 64;

    private readonly Dictionary<string, Expr> _definitions = new(StringComparer.Ordinal);
    private readonly Dictionary<string, Scalar?> _temporaries = new(StringComparer.Ordinal);
    private readonly Dictionary<Expr, Scalar?> _lifted = new();
    private readonly Dictionary<Scalar, Scalar?> _expanded = new();

    /// <summary>Temporaries are read on demand: most passes ask about a few statements of a large block.</summary>
    public PolynomialValues(CodeBlock block)
    {
        foreach (var temp in block.Temporaries) _definitions[temp.Target] = temp.Value;
    }

    /// <summary>The value of a temporary or input by name: its polynomial, or the variable itself.</summary>
    public Scalar OfName(string name) => Polynomial(name) ?? Scalar.Variable(name);

    /// <summary>The polynomial a temporary holds, or null for an input or a temporary that is not one.</summary>
    private Scalar? Polynomial(string name)
    {
        if (_temporaries.TryGetValue(name, out var known)) return known;
        if (!_definitions.TryGetValue(name, out var definition)) return null;
        _temporaries[name] = null; // single assignment: a definition never reads itself, this only guards malformed blocks
        return _temporaries[name] = Of(definition);
    }

    /// <summary>The expression's value, or null when it is not a polynomial of the block's names or grows too large.</summary>
    public Scalar? Of(Expr e)
    {
        if (!PolynomialLifting.TryLift(e, _lifted, out var lifted) || lifted.Terms.Count > MaxTerms) return null;
        if (_expanded.TryGetValue(lifted, out var known)) return known;
        return _expanded[lifted] = Expand(lifted);
    }

    private Scalar? Expand(Scalar lifted)
    {
        if (!lifted.Variables.Any(v => Polynomial(v) is not null)) return lifted;
        var sum = Scalar.Zero;
        foreach (var term in lifted.TermArray)
        {
            long size = 1;
            var product = Scalar.Constant(term.Coefficient);
            foreach (var f in term.Monomial.FactorArray)
            {
                var value = (f.Atom.Kind == AtomKind.Variable ? Polynomial(f.Atom.Name) : null) ?? f.Atom.AsScalar();
                for (var k = 0; k < f.Power; k++) size *= value.Terms.Count;
                if (f.Power < 0 || size > 4 * MaxTerms) return null;
                product *= Scalar.IntegerPower(value, f.Power);
            }
            sum += product;
            if (sum.Terms.Count > 4 * MaxTerms) return null;
        }
        return sum.Terms.Count > MaxTerms ? null : sum;
    }
}
