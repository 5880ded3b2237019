using System.Runtime.CompilerServices;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// Reduces scalars modulo polynomial relations known to hold: the Pythagorean identity
/// sin(u)^2 + cos(u)^2 = 1 for every sin atom (applied as sin(u)^2 → 1 - cos(u)^2, so that
/// sin^2 + cos^2 gives 1 and 1 - sin^2 gives cos^2) and its twin cosh(u)^2 - sinh(u)^2 = 1, plus user relations such as the unit norm of
/// a rotor, each solved for one chosen monomial. Reduction also applies inside function arguments.
/// Immutable; <see cref="With(Scalar, Scalar, Scalar)"/> returns an extended set.
/// </summary>
public sealed class SideRelations
{
    // Each pass applies every rule once; a sound rule set ends long before this.
    private const int MaxPasses = 256;

    private readonly SideRelation[] _rules;

    private SideRelations(bool pythagorean, SideRelation[] rules)
    {
        UsesPythagoreanIdentity = pythagorean;
        _rules = rules;
    }

    /// <summary>No relations at all.</summary>
    public static SideRelations None { get; } = new(false, []);

    /// <summary>Only sin(u)^2 + cos(u)^2 = 1.</summary>
    public static SideRelations Trigonometric { get; } = new(true, []);

    public bool UsesPythagoreanIdentity { get; }

    public IReadOnlyList<SideRelation> Rules => _rules;

    public bool IsEmpty => !UsesPythagoreanIdentity && _rules.Length == 0;

    /// <summary>
    /// Adds the relation <paramref name="left"/> = <paramref name="right"/>, solved for the monomial
    /// of <paramref name="eliminate"/> (a single term, e.g. w^2), which must occur in the relation
    /// and must not occur again in its solution.
    /// </summary>
    public SideRelations With(Scalar left, Scalar right, Scalar eliminate)
    {
        ArgumentNullException.ThrowIfNull(left);
        ArgumentNullException.ThrowIfNull(right);
        ArgumentNullException.ThrowIfNull(eliminate);
        if (eliminate.Terms.Count != 1 || eliminate.IsConstant)
            throw new ArgumentException($"The eliminated part must be a single non-constant monomial such as w^2, not '{eliminate}'.", nameof(eliminate));
        var pattern = eliminate.Terms[0].Monomial;
        foreach (var factor in pattern.FactorArray)
            if (factor.Power < 0)
                throw new ArgumentException($"The eliminated monomial '{pattern}' must have positive powers only.", nameof(eliminate));
        var relation = left - right;
        Rational? coefficient = null;
        foreach (var term in relation.TermArray)
            if (ReferenceEquals(term.Monomial, pattern)) coefficient = term.Coefficient;
        if (coefficient is not { } k)
            throw new ArgumentException($"The relation {left} = {right} does not contain '{pattern}', so it cannot be solved for it.", nameof(eliminate));
        var rest = relation - Scalar.FromTerm(k, pattern);
        var replacement = Scalar.Scale(rest, -k.Reciprocal());
        foreach (var term in replacement.TermArray)
            if (Monomial.TryDivide(term.Monomial, pattern) is not null)
                throw new ArgumentException($"Solving {left} = {right} for '{pattern}' gives '{replacement}', which contains it again.", nameof(eliminate));
        return new SideRelations(UsesPythagoreanIdentity, [.. _rules, new SideRelation(pattern, replacement)]);
    }

    /// <summary>Adds the relation with the Pythagorean identity kept or dropped as in this set.</summary>
    public SideRelations With(SideRelation rule) => new(UsesPythagoreanIdentity, [.. _rules, rule]);

    public Scalar Reduce(Scalar value)
    {
        ArgumentNullException.ThrowIfNull(value);
        if (IsEmpty) return value;
        return Reduce(value, new Dictionary<Atom, Scalar>());
    }

    private Scalar Reduce(Scalar value, Dictionary<Atom, Scalar> memo)
    {
        // Arguments first, so that e.g. sqrt(w^2 + x^2 + y^2 + z^2) becomes sqrt(1) = 1.
        var current = Scalar.MapAtoms(value, atom => atom.ArgumentArray.Length == 0 ? null : ReducedAtom(atom), memo);
        for (var pass = 0; pass < MaxPasses; pass++)
        {
            var next = ReduceOnce(current);
            if (next is null) return current;
            current = next;
        }
        throw new InvalidOperationException($"The side relations [{this}] do not terminate on '{value}'.");
    }

    /// <summary>
    /// What each function atom becomes once its arguments are reduced. The relations are fixed, so
    /// the answer is too: it is shared by every call (a large argument such as the denominator of
    /// every output is otherwise reduced again for each expression that divides by it).
    /// </summary>
    private readonly ConditionalWeakTable<Atom, Scalar> _reducedAtoms = new();

    private Scalar ReducedAtom(Atom atom)
    {
        if (_reducedAtoms.TryGetValue(atom, out var known)) return known;
        var reduced = ReduceArguments(atom, new Dictionary<Atom, Scalar>());
        _reducedAtoms.AddOrUpdate(atom, reduced);
        return reduced;
    }

    private Scalar ReduceArguments(Atom atom, Dictionary<Atom, Scalar> memo)
    {
        var arguments = atom.ArgumentArray;
        var reduced = new Scalar[arguments.Length];
        var changed = false;
        for (var i = 0; i < arguments.Length; i++)
        {
            reduced[i] = Reduce(arguments[i], memo);
            changed |= !ReferenceEquals(reduced[i], arguments[i]);
        }
        return changed ? Scalar.Apply(atom.Kind, reduced) : atom.AsScalar();
    }

    /// <summary>One rewrite step on every reducible term, or null when no term is reducible.</summary>
    private Scalar? ReduceOnce(Scalar value)
    {
        List<Term>? kept = null;
        var rewritten = new ScalarSumBuilder();
        var terms = value.TermArray;
        for (var i = 0; i < terms.Length; i++)
        {
            var term = terms[i];
            var step = RewriteTerm(term);
            if (step is null)
            {
                kept?.Add(term);
                continue;
            }
            if (kept is null)
            {
                kept = new List<Term>(terms.Length);
                for (var j = 0; j < i; j++) kept.Add(terms[j]);
            }
            rewritten.Add(step);
        }
        if (kept is null) return null;
        foreach (var term in kept) rewritten.Add(term);
        return rewritten.ToScalar();
    }

    private Scalar? RewriteTerm(Term term)
    {
        foreach (var rule in _rules)
        {
            var quotient = Monomial.TryDivide(term.Monomial, rule.Pattern);
            if (quotient is not null) return Scalar.FromTerm(term.Coefficient, quotient) * rule.Replacement;
        }
        if (!UsesPythagoreanIdentity) return null;
        foreach (var factor in term.Monomial.FactorArray)
        {
            if (factor.Atom.Kind is not (AtomKind.Sin or AtomKind.Sinh) || factor.Power < 2) continue;
            var quotient = Monomial.TryDivide(term.Monomial, Monomial.FromAtom(factor.Atom, 2))!;
            if (factor.Atom.Kind == AtomKind.Sinh)
            {
                // sinh(u)^2 → cosh(u)^2 - 1, the hyperbolic twin (the atoms are new, so cache keys need not change)
                var cosh = Scalar.HyperbolicCosine(factor.Atom.ArgumentArray[0]);
                return Scalar.FromTerm(term.Coefficient, quotient) * (cosh * cosh - Scalar.One);
            }
            // sin(u)^2 → 1 - cos(u)^2
            var cos = Scalar.Cos(factor.Atom.ArgumentArray[0]);
            return Scalar.FromTerm(term.Coefficient, quotient) * (Scalar.One - cos * cos);
        }
        return null;
    }

    /// <summary>Canonical text of the relation set, used in cache keys.</summary>
    public override string ToString()
    {
        var parts = new List<string>();
        if (UsesPythagoreanIdentity) parts.Add("sin^2+cos^2=1");
        foreach (var rule in _rules) parts.Add(rule.ToString());
        return string.Join("; ", parts);
    }
}
