using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>
/// Writes an expression linear in cos φ, A + cos φ·B, as its value at φ = 0 plus a versine term:
/// (A + B) + (cos φ − 1)·B. A rotation is the identity at angle zero, so A + B collapses to the
/// rotated vector itself and the expanded sandwich becomes Rodrigues' x + sin φ (k × x) +
/// (1 − cos φ)(k × (k × x)). Kept only when A + B has fewer terms than A.
/// </summary>
public static class AngleZeroSplit
{
    public static bool TrySplit(Scalar e, out Scalar atZero, out Atom cosine, out Scalar cofactor)
    {
        atZero = e;
        cofactor = Scalar.Zero;
        cosine = null!;
        if (e.Terms.Count < 3) return false;
        var candidates = e.Terms.SelectMany(t => t.Monomial.Factors).Where(f => f.Atom.Kind == AtomKind.Cos).Select(f => f.Atom).Distinct().Order();
        foreach (var atom in candidates)
        {
            var with = new List<Term>();
            var without = new List<Term>();
            var linear = true;
            foreach (var t in e.TermArray)
            {
                var power = t.Monomial.PowerOf(atom);
                if (power == 0) without.Add(t);
                else if (power == 1) with.Add(new Term(t.Coefficient, Monomial.WithPower(t.Monomial, atom, 0)));
                else { linear = false; break; }
            }
            if (!linear || with.Count == 0) continue;
            var a = Scalar.FromTerms(without);
            var b = Scalar.FromTerms(with);
            var zero = a + b;
            if (zero.Terms.Count >= a.Terms.Count) continue;
            atZero = zero;
            cofactor = b;
            cosine = atom;
            return true;
        }
        return false;
    }
}
