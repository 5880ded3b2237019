using System.Runtime.CompilerServices;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Turns a canonical symbolic scalar (a sum of monomials) into an expression tree, factoring as
/// it goes: a numeric factor shared by every term is pulled out, and then, greedily, the atom
/// found in the most terms (a Horner-like scheme), which never adds a multiplication and saves
/// one for every extra term that shares the atom. Between atoms found in as many terms, each is
/// tried and the one whose lowering costs least goes out first, so that the result does not
/// depend on the names the binding gave the inputs (the order in which they were bound).
/// </summary>
public static class ScalarLowering
{
    private sealed record PolyTerm(Rational Coefficient, Dictionary<Atom, int> Powers);

    /// <summary>
    /// Lowering without a spread depends on the scalar alone, and the same arguments (the
    /// denominator every output divides by, the radicand of a norm) are lowered again for every
    /// expression that holds them: the trees are immutable, so one is made per scalar and shared.
    /// </summary>
    public static Expr Lower(Scalar s) => Lowered.GetValue(s, static s => Lower(s, null));

    private static readonly ConditionalWeakTable<Scalar, Expr> Lowered = new();

    /// <param name="spread">
    /// For each atom, how many statements of the block read it. Between atoms shared by as many
    /// terms, the one fewer statements read goes out first, so what is left inside is the part
    /// the statements have in common and common-subexpression elimination can share it
    /// (t₁ = d₂·u and t₂ = d₁·u with u = d⌋B computed once).
    /// </param>
    public static Expr Lower(Scalar s, IReadOnlyDictionary<Atom, int>? spread)
    {
        if (Rewrites.AngleZeroSplit.TrySplit(s, out var atZero, out var cosine, out var cofactor))
            return ExprFactory.Sum(Lower(atZero, spread), ExprFactory.Product(ExprFactory.Sum(LowerAtom(cosine), ConstantExpr.From(-1)), Lower(cofactor, spread)));
        return LowerSum(s.Terms.Select(ToPolyTerm).ToList(), spread, lookahead: true);
    }

    // Trying every tied atom lowers the sum once per candidate, greedily below it: bounded so that
    // a large output (a sphere through four points) is not lowered dozens of times.
    private const int MaxLookaheadTerms = 48;
    private const int MaxLookaheadCandidates = 6;

    private static PolyTerm ToPolyTerm(Term t) =>
        new(t.Coefficient, t.Monomial.Factors.ToDictionary(f => f.Atom, f => f.Power));

    private static Expr LowerSum(List<PolyTerm> terms, IReadOnlyDictionary<Atom, int>? spread, bool lookahead = false)
    {
        if (terms.Count == 0) return ConstantExpr.Zero;
        if (terms.Count == 1) return LowerTerm(terms[0]);

        // A numeric factor common to all terms: 2xy − 2wz → 2(xy − wz).
        var magnitude = terms[0].Coefficient.Abs();
        if (!magnitude.IsOne && terms.All(t => t.Coefficient.Abs() == magnitude))
            return FactorCoefficient(terms, magnitude, spread, lookahead);

        var tied = SharedAtoms(terms, spread);
        if (tied.Count == 0) return LowerByCoefficientGroups(terms, spread, lookahead);
        if (!lookahead || tied.Count == 1 || terms.Count > MaxLookaheadTerms) return FactorOut(terms, tied[0], spread, lookahead);
        // the first of the cheapest, greedily lowered below it; then lowered again with lookahead
        var best = tied.Take(MaxLookaheadCandidates)
            .Select((atom, i) => (Atom: atom, Cost: CodeStatistics.CostOf(FactorOut(terms, atom, spread, lookahead: false)), Index: i))
            .OrderBy(c => c.Cost).ThenBy(c => c.Index).First().Atom;
        return FactorOut(terms, best, spread, lookahead);
    }

    private static Expr FactorOut(List<PolyTerm> terms, Atom best, IReadOnlyDictionary<Atom, int>? spread, bool lookahead)
    {
        var with = new List<PolyTerm>();
        var without = new List<PolyTerm>();
        foreach (var t in terms)
        {
            if (t.Powers.TryGetValue(best, out var p) && p > 0)
            {
                var powers = new Dictionary<Atom, int>(t.Powers);
                if (p == 1) powers.Remove(best); else powers[best] = p - 1;
                with.Add(t with { Powers = powers });
            }
            else without.Add(t);
        }
        var factored = best.Kind == AtomKind.Inverse
            ? ExprFactory.Quotient(LowerSum(with, spread, lookahead), Lower(best.Arguments[0]))
            : ExprFactory.Product(LowerAtom(best), LowerSum(with, spread, lookahead));
        return without.Count == 0 ? factored : ExprFactory.Sum(factored, LowerSum(without, spread, lookahead));
    }

    /// <summary>
    /// With no atom to share, terms with the same coefficient magnitude share it instead:
    /// 1 − 2y² − 2z² → 1 − 2(y² + z²), one product fewer.
    /// </summary>
    private static Expr LowerByCoefficientGroups(List<PolyTerm> terms, IReadOnlyDictionary<Atom, int>? spread, bool lookahead)
    {
        var group = terms.Where(t => !t.Coefficient.Abs().IsOne)
            .GroupBy(t => t.Coefficient.Abs())
            .Where(g => g.Count() >= 2)
            .OrderByDescending(g => g.Count())
            .FirstOrDefault();
        if (group is null) return ExprFactory.Sum(terms.Select(LowerTerm));
        var magnitude = group.Key;
        var grouped = FactorCoefficient(group.ToList(), magnitude, spread, lookahead);
        var others = terms.Where(t => t.Coefficient.Abs() != magnitude).ToList();
        return others.Count == 0 ? grouped : ExprFactory.Sum(grouped, LowerSum(others, spread, lookahead));
    }

    /// <summary>c·(Σ tᵢ/c), with c taking the sign when every term is negative: −2y² − 2z² → −2(y² + z²).</summary>
    private static Expr FactorCoefficient(List<PolyTerm> terms, Rational magnitude, IReadOnlyDictionary<Atom, int>? spread, bool lookahead)
    {
        var factor = terms.All(t => t.Coefficient.Sign < 0) ? -magnitude : magnitude;
        return ExprFactory.Product(ConstantExpr.From(factor), LowerSum(terms.Select(t => t with { Coefficient = t.Coefficient / factor }).ToList(), spread, lookahead));
    }

    /// <summary>
    /// The atoms with a positive power in the most terms (at least two) that fewest statements
    /// read, in the canonical order: the first is the greedy choice, the others tie with it.
    /// </summary>
    private static List<Atom> SharedAtoms(List<PolyTerm> terms, IReadOnlyDictionary<Atom, int>? spread)
    {
        var counts = new Dictionary<Atom, int>();
        foreach (var t in terms)
        foreach (var (atom, power) in t.Powers)
            if (power > 0) counts[atom] = counts.GetValueOrDefault(atom) + 1;
        var most = counts.Count == 0 ? 0 : counts.Values.Max();
        if (most < 2) return [];
        var tied = counts.Where(kv => kv.Value == most).Select(kv => kv.Key).ToList();
        tied.Sort((a, b) => a == b ? 0 : IsPreferred(a, b, spread) ? -1 : 1);
        // only the canonical (name) order is left to decide between these
        var spreadOfFirst = spread?.GetValueOrDefault(tied[0]) ?? 0;
        return tied.TakeWhile(a => (spread?.GetValueOrDefault(a) ?? 0) == spreadOfFirst).ToList();
    }

    /// <summary>On a tie, the atom fewer statements read, then the canonical order.</summary>
    private static bool IsPreferred(Atom atom, Atom best, IReadOnlyDictionary<Atom, int>? spread)
    {
        var bySpread = spread is null ? 0 : spread.GetValueOrDefault(atom).CompareTo(spread.GetValueOrDefault(best));
        return bySpread != 0 ? bySpread < 0 : atom.CompareTo(best) < 0;
    }

    private static Expr LowerTerm(PolyTerm t)
    {
        var numerator = new List<Expr> { ConstantExpr.From(t.Coefficient) };
        var denominator = new List<Expr>();
        foreach (var (atom, power) in t.Powers.OrderBy(kv => kv.Key))
        {
            if (atom.Kind == AtomKind.Inverse)
            {
                // inv(s)^p: s^p in the denominator (or the numerator for negative p)
                var s = Lower(atom.Arguments[0]);
                (power > 0 ? denominator : numerator).Add(ExprFactory.Power(s, Math.Abs(power)));
            }
            else
            {
                (power > 0 ? numerator : denominator).Add(ExprFactory.Power(LowerAtom(atom), Math.Abs(power)));
            }
        }
        var top = ExprFactory.Product(numerator);
        return denominator.Count == 0 ? top : ExprFactory.Quotient(top, ExprFactory.Product(denominator));
    }

    private static Expr LowerAtom(Atom atom) => atom.Kind switch
    {
        AtomKind.Variable => ExprFactory.Variable(atom.Name),
        AtomKind.Pi => new ConstantExpr(Math.PI),
        AtomKind.Inverse => ExprFactory.Quotient(ConstantExpr.One, Lower(atom.Arguments[0])),
        AtomKind.Sin => ExprFactory.Call("sin", Lower(atom.Arguments[0])),
        AtomKind.Cos => ExprFactory.Call("cos", Lower(atom.Arguments[0])),
        AtomKind.Tan => ExprFactory.Call("tan", Lower(atom.Arguments[0])),
        AtomKind.Sqrt => ExprFactory.Call("sqrt", Lower(atom.Arguments[0])),
        AtomKind.Exp => ExprFactory.Call("exp", Lower(atom.Arguments[0])),
        AtomKind.Log => ExprFactory.Call("log", Lower(atom.Arguments[0])),
        AtomKind.Abs => ExprFactory.Call("abs", Lower(atom.Arguments[0])),
        AtomKind.Atan2 => ExprFactory.Call("atan2", Lower(atom.Arguments[0]), Lower(atom.Arguments[1])),
        AtomKind.Pow => ExprFactory.Call("pow", Lower(atom.Arguments[0]), Lower(atom.Arguments[1])),
        AtomKind.Sinh => ExprFactory.Call("sinh", Lower(atom.Arguments[0])),
        AtomKind.Cosh => ExprFactory.Call("cosh", Lower(atom.Arguments[0])),
        _ => throw new InvalidOperationException($"No lowering for atom kind {atom.Kind}."),
    };
}
