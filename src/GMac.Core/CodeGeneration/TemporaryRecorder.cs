using GMac.Core.Algebra;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Names the coefficients of intermediate multivectors during symbolic evaluation. Each
/// non-trivial coefficient becomes a temporary variable whose definition is kept, so later
/// operations work on short expressions in temporaries instead of expanded polynomials in the
/// inputs. This preserves the structure of the GA computation (e.g. (v3 − v1) ∧ (v2 − v1) costs
/// two products, where its expansion costs six).
/// Temporaries hide identities, though: the quasi-norm of a rotor is 1 only when written in the
/// inputs. So denominators and square-root arguments are also expanded back into the inputs and
/// simplified, and the expanded form is used whenever it is shorter.
/// </summary>
public sealed class TemporaryRecorder
{
    public const string Prefix = "_gmac_t";

    private readonly List<(string Name, Scalar Value)> _temporaries = [];
    private readonly Dictionary<Scalar, Scalar> _byValue = new();
    private readonly Dictionary<string, Lazy<Scalar>> _expanded = new(StringComparer.Ordinal);
    private readonly Dictionary<Scalar, Scalar?> _expandedArguments = new();
    private readonly Func<Scalar, Scalar> _simplify;

    public TemporaryRecorder(Func<Scalar, Scalar>? simplify = null, bool statementsOnly = false)
    {
        _simplify = simplify ?? (s => s);
        StatementsOnly = statementsOnly;
    }

    /// <summary>
    /// Whether only the results of whole statements should be named, not every subexpression:
    /// coarser naming leaves more to the symbolic form, which sometimes cancels more.
    /// </summary>
    public bool StatementsOnly { get; }

    /// <summary>Temporaries in definition order; each value reads only inputs and earlier temporaries.</summary>
    public IReadOnlyList<(string Name, Scalar Value)> Temporaries => _temporaries;

    public static bool IsTemporary(string variableName) => variableName.StartsWith(Prefix, StringComparison.Ordinal);

    public Multivector<Scalar> Record(Multivector<Scalar> value) => value.MapCoefficients(Record);

    public Scalar Record(Scalar value)
    {
        value = _simplify(ExpandDenominators(value));
        if (IsTrivial(value)) return value;
        if (_byValue.TryGetValue(value, out var existing)) return existing;
        if (_byValue.TryGetValue(-value, out var negated)) return -negated;
        var name = $"{Prefix}{_temporaries.Count}";
        var variable = Scalar.Variable(name);
        _temporaries.Add((name, value));
        _expanded[name] = new Lazy<Scalar>(() => _simplify(Expand(value)));
        _byValue[value] = variable;
        return variable;
    }

    /// <summary>The value with every temporary replaced by its definition, down to the inputs.</summary>
    public Scalar Expand(Scalar value)
    {
        if (!value.Variables.Any(IsTemporary)) return value;
        var map = value.Variables.Where(IsTemporary).ToDictionary(v => v, v => _expanded[v].Value, StringComparer.Ordinal);
        return value.Substitute(map);
    }

    private Scalar ExpandDenominators(Scalar value)
    {
        foreach (var atom in value.Atoms().Where(a => a.Kind is AtomKind.Inverse or AtomKind.Sqrt).ToArray())
        {
            var argument = atom.Arguments[0];
            if (!argument.Variables.Any(IsTemporary)) continue;
            if (TryExpand(argument) is not { } expanded || expanded.Terms.Count >= argument.Terms.Count) continue;
            var replacement = atom.Kind == AtomKind.Inverse ? Scalar.Reciprocal(expanded) : Scalar.Sqrt(expanded);
            value = InverseCancellation.ReplaceAtoms(value, new Dictionary<Atom, Scalar> { [atom] = replacement });
        }
        return value;
    }

    /// <summary>
    /// The value expanded into the inputs and simplified; null when that expansion is too large to
    /// form (the norm of a general inverse in 5D is a polynomial of degree 8 in 32 coefficients).
    /// </summary>
    private Scalar? TryExpand(Scalar value)
    {
        // Every coefficient of A/s divides by the same s: expand it once.
        if (_expandedArguments.TryGetValue(value, out var known)) return known;
        Scalar? expanded;
        try
        {
            expanded = _simplify(Expand(value));
        }
        catch (AlgebraException e) when (e.ExceedsLimit)
        {
            expanded = null;
        }
        _expandedArguments[value] = expanded;
        return expanded;
    }

    /// <summary>A constant, or a constant multiple of one variable: naming it would save nothing.</summary>
    private static bool IsTrivial(Scalar s) =>
        s.IsConstant || (s.Terms.Count == 1 && s.Terms[0].Monomial.Factors is [{ Power: 1, Atom.Kind: AtomKind.Variable }]);
}
