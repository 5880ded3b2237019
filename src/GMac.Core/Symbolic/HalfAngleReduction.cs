using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// Rewrites products of sines and cosines of a half angle u = w/2 into functions of w:
/// sin u cos u = sin(w)/2, cos²u = (1 + cos w)/2, sin²u = (1 − cos w)/2. Versors are built from
/// half angles (cos(φ/2) − sin(φ/2) B), and a sandwich product V X Ṽ is quadratic in them; after
/// this rewrite it is linear in cos φ and sin φ, the form of Rodrigues' rotation formula.
/// </summary>
public static class HalfAngleReduction
{
    public static Scalar Apply(Scalar value)
    {
        // only the terms' own factors are reduced; deeper ones leave every term as it is
        if (!value.FactorAtoms.Any(IsHalfAngleTrig)) return value;
        // A term with at most one sine or cosine of each half angle stays as it is: rebuilding it
        // factor by factor gave the same term back, and did so for nearly nine in ten of the
        // inverse kinematics' scalars (over half of that macro's generation time).
        var terms = value.TermArray;
        if (!terms.Any(Reducible)) return value;
        var sum = new ScalarSumBuilder();
        foreach (var term in terms)
        {
            if (Reducible(term)) sum.Add(Reduce(term));
            else sum.Add(term);
        }
        return sum.ToScalar();
    }

    /// <summary>Whether some half angle's sine and cosine powers in the term add up to two or more.</summary>
    private static bool Reducible(Term term)
    {
        List<Scalar>? seen = null;
        foreach (var f in term.Monomial.FactorArray)
        {
            if (f.Power <= 0 || !IsHalfAngleTrig(f.Atom)) continue;
            if (f.Power >= 2) return true;
            var u = f.Atom.Arguments[0];
            seen ??= [];
            if (seen.Contains(u)) return true;
            seen.Add(u);
        }
        return false;
    }

    private static bool IsHalfAngleTrig(Atom a) => a.Kind is AtomKind.Sin or AtomKind.Cos && IsHalf(a.Arguments[0]);

    /// <summary>True when every coefficient of the argument has denominator 2 exactly (so 2u has integer ones).</summary>
    private static bool IsHalf(Scalar u) => u.Terms.Count > 0 && u.Terms.All(t => t.Coefficient.Denominator == 2);

    private static Scalar Reduce(Term term)
    {
        // powers of sin(u) and cos(u) per half-angle argument u; everything else stays
        var powers = new Dictionary<Scalar, (int Sin, int Cos)>();
        var others = new List<Factor>(term.Monomial.FactorArray.Length);
        foreach (var f in term.Monomial.FactorArray)
        {
            if (f.Power > 0 && IsHalfAngleTrig(f.Atom))
            {
                var u = f.Atom.Arguments[0];
                var (s, c) = powers.GetValueOrDefault(u);
                powers[u] = f.Atom.Kind == AtomKind.Sin ? (s + f.Power, c) : (s, c + f.Power);
            }
            else others.Add(f);
        }
        // the other factors as they are, one term: a subset of a valid monomial's factors
        var rest = Scalar.FromTerm(term.Coefficient, Monomial.Create(others));
        var half = Scalar.Constant(new Rational(1, 2));
        foreach (var (u, (sinPower, cosPower)) in powers)
        {
            var w = u + u;
            var (s, c) = (sinPower, cosPower);
            var factor = Scalar.One;
            for (; s >= 1 && c >= 1; s--, c--) factor *= Scalar.Sin(w) * half;
            for (; c >= 2; c -= 2) factor *= (Scalar.One + Scalar.Cos(w)) * half;
            for (; s >= 2; s -= 2) factor *= (Scalar.One - Scalar.Cos(w)) * half;
            if (s == 1) factor *= Scalar.Sin(u);
            if (c == 1) factor *= Scalar.Cos(u);
            rest *= factor;
        }
        return rest;
    }
}
