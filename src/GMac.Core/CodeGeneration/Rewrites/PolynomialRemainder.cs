using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>
/// Multivariate division with remainder, b = q·s + r, in a lexicographic order whose first atom
/// is chosen by the caller (every atom, sin and inverses included, acts as a variable). No term
/// of r is divisible by the leading term of s, so r is the part of b that s cannot absorb.
/// </summary>
internal static class PolynomialRemainder
{
    private const int MaxSteps = 4_000;

    /// <returns>false when the division would take too many steps.</returns>
    public static bool TryDivide(Scalar b, Scalar s, Atom first, out Scalar quotient, out Scalar remainder)
    {
        quotient = Scalar.Zero;
        remainder = b;
        if (Scalar.IsZero(s) || Scalar.IsZero(b)) return false;
        int Order(Monomial x, Monomial y) => Compare(x, y, first);
        var lead = DivisionTerms.Leading(s.Terms, Order);
        var rest = new DividendTerms(b, Order);
        var q = new List<Term>();
        var r = new List<Term>();
        for (var step = 0; rest.Count > 0; step++)
        {
            if (step == MaxSteps) return false;
            var top = rest.Leading();
            var factor = Divide(top.Monomial, lead.Monomial);
            if (factor is null)
            {
                r.Add(top);
                rest.Remove(top.Monomial);
                continue;
            }
            var t = new Term(top.Coefficient / lead.Coefficient, factor);
            q.Add(t);
            rest.SubtractMultiple(t, s, lead.Monomial, top.Monomial);
        }
        quotient = Scalar.FromTerms(q);
        remainder = Scalar.FromTerms(r);
        return true;
    }

    private static int Power(Monomial m, Atom atom)
    {
        foreach (var f in m.FactorArray)
            if (ReferenceEquals(f.Atom, atom)) return f.Power;
        return 0;
    }

    /// <summary>The power of <paramref name="first"/> decides, then the atoms in descending canonical order.</summary>
    private static int Compare(Monomial a, Monomial b, Atom first)
    {
        var c = Power(a, first).CompareTo(Power(b, first));
        return c != 0 ? c : DivisionTerms.CompareDescendingAtoms(a, b);
    }

    /// <summary>m / d when d's powers do not exceed m's (only positive powers divide).</summary>
    private static Monomial? Divide(Monomial m, Monomial d)
    {
        foreach (var f in d.FactorArray)
            if (f.Power <= 0) return null;
        return Monomial.TryDivide(m, d);
    }

    /// <summary>
    /// Whether the division in the order led by <paramref name="first"/> can give a quotient at all:
    /// when no term of b is divisible by the leading term of s, every step moves a term of b to the
    /// remainder and the quotient stays zero, so the division need not be run.
    /// </summary>
    public static bool CanDivide(Scalar b, Scalar s, Atom first)
    {
        if (Scalar.IsZero(s) || Scalar.IsZero(b)) return false;
        var lead = DivisionTerms.Leading(s.Terms, (x, y) => Compare(x, y, first)).Monomial;
        foreach (var t in b.TermArray)
            if (Divide(t.Monomial, lead) is not null) return true;
        return false;
    }

    /// <summary>Atoms that may lead the order: those of s with a positive power.</summary>
    public static IEnumerable<Atom> Candidates(Scalar s) =>
        s.Terms.SelectMany(t => t.Monomial.Factors).Where(f => f.Power > 0).Select(f => f.Atom).Distinct().Order();

    public static Rational LeadCoefficient(Scalar s) => s.Terms[0].Coefficient;
}
