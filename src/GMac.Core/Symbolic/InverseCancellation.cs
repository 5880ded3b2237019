namespace GMac.Core.Symbolic;

/// <summary>
/// Cancels a sum s against its inverse atom 1/s: an expression B·(1/s) + R whose cofactor B is an
/// exact polynomial multiple of s, B = Q·s, becomes Q + R. Exact division uses the multivariate
/// division algorithm in lexicographic order, every atom (sin, sqrt, other inverses…) acting as a
/// variable. This is what turns (x² + y²)/(x² + y²) into 1 and the quasi-norm of a rotor built
/// from a normalized axis into cos² + sin², which the side relations finish.
/// </summary>
public static class InverseCancellation
{
    private const int MaxDivisionSteps = 20_000;

    /// <summary>Cancels inside every function argument first (e.g. within a denominator), then at the top.</summary>
    public static Scalar CancelDeep(Scalar e) => Cancel(MapArguments(e, CancelDeep));

    /// <summary>The scalar with each function atom rebuilt over transformed arguments.</summary>
    public static Scalar MapArguments(Scalar e, Func<Scalar, Scalar> map)
    {
        // Only the terms' own factors: atoms nested deeper are rebuilt by the recursion on their
        // arguments, and a replacement listed for them would match no factor here.
        var atoms = e.FactorAtoms.Where(a => a.Arguments.Count > 0).ToArray();
        if (atoms.Length == 0) return e;
        var replaced = new Dictionary<Atom, Scalar>();
        foreach (var atom in atoms)
        {
            var args = atom.Arguments.Select(map).ToArray();
            if (args.Select((a, i) => ReferenceEquals(a, atom.Arguments[i])).All(same => same)) continue;
            replaced[atom] = Rebuild(atom.Kind, args);
        }
        return replaced.Count == 0 ? e : ReplaceAtoms(e, replaced);
    }

    /// <summary>The scalar with the given atoms replaced by values (powers kept).</summary>
    public static Scalar ReplaceAtoms(Scalar e, IReadOnlyDictionary<Atom, Scalar> replacements)
    {
        var sum = new ScalarSumBuilder();
        foreach (var term in e.TermArray)
        {
            var product = Scalar.Constant(term.Coefficient);
            foreach (var f in term.Monomial.FactorArray)
                product *= Scalar.IntegerPower(replacements.TryGetValue(f.Atom, out var r) ? r : f.Atom.AsScalar(), f.Power);
            sum.Add(product);
        }
        return sum.ToScalar();
    }

    private static Scalar Rebuild(AtomKind kind, Scalar[] a) => kind switch
    {
        AtomKind.Sin => Scalar.Sin(a[0]),
        AtomKind.Cos => Scalar.Cos(a[0]),
        AtomKind.Tan => Scalar.Tan(a[0]),
        AtomKind.Sqrt => Scalar.Sqrt(a[0]),
        AtomKind.Exp => Scalar.Exp(a[0]),
        AtomKind.Log => Scalar.Log(a[0]),
        AtomKind.Abs => Scalar.Abs(a[0]),
        AtomKind.Atan2 => Scalar.Atan2(a[0], a[1]),
        AtomKind.Pow => Scalar.Pow(a[0], a[1]),
        AtomKind.Inverse => Scalar.Reciprocal(a[0]),
        AtomKind.Sinh => Scalar.HyperbolicSine(a[0]),
        AtomKind.Cosh => Scalar.HyperbolicCosine(a[0]),
        _ => throw new InvalidOperationException($"Atom kind {kind} has no arguments to rebuild."),
    };

    public static Scalar Cancel(Scalar e)
    {
        for (var round = 0; round < 16; round++)
        {
            var changed = false;
            // an inverse nested in an argument has no cofactor at this level
            foreach (var atom in e.FactorAtoms.Where(a => a.Kind == AtomKind.Inverse).OrderBy(a => a).ToArray())
            {
                var (cofactor, rest) = Split(e, atom);
                if (Scalar.IsZero(cofactor)) continue;
                if (!TryDivide(cofactor, atom.Arguments[0], out var quotient)) continue;
                e = quotient + rest;
                changed = true;
                break;
            }
            if (!changed) break;
        }
        return e;
    }

    /// <summary>e = cofactor·atom + rest, where rest has no positive power of the atom.</summary>
    private static (Scalar Cofactor, Scalar Remaining) Split(Scalar e, Atom atom)
    {
        var cofactor = new List<Term>();
        var rest = new List<Term>();
        foreach (var t in e.TermArray)
        {
            var power = t.Monomial.PowerOf(atom);
            if (power > 0) cofactor.Add(new Term(t.Coefficient, Monomial.WithPower(t.Monomial, atom, power - 1)));
            else rest.Add(t);
        }
        return (Scalar.FromOwnedTerms(cofactor), Scalar.FromOwnedTerms(rest));
    }

    /// <summary>Exact division b / s; false when a remainder is left.</summary>
    public static bool TryDivide(Scalar b, Scalar s, out Scalar quotient)
    {
        quotient = Scalar.Zero;
        if (Scalar.IsZero(s)) return false;
        if (!SpansAllow(b, s)) return false;
        var lead = DivisionTerms.Leading(s.Terms, DivisionTerms.CompareDescendingAtoms);
        var remainder = new DividendTerms(b, DivisionTerms.CompareDescendingAtoms);
        var q = new List<Term>();
        for (var step = 0; step < MaxDivisionSteps && remainder.Count > 0; step++)
        {
            var top = remainder.Leading();
            var factor = Divide(top.Monomial, lead.Monomial);
            if (factor is null) return false; // the leading term is not divisible: a remainder stays
            var t = new Term(top.Coefficient / lead.Coefficient, factor);
            q.Add(t);
            remainder.SubtractMultiple(t, s, lead.Monomial, top.Monomial);
        }
        if (remainder.Count > 0) return false;
        quotient = Scalar.FromTerms(q);
        return true;
    }

    /// <summary>
    /// A necessary condition for b = q·s: in every atom, the spread of b's powers (highest minus lowest)
    /// is at least s's, since a product's spread in an atom is the sum of its factors' spreads. Most
    /// divisions that fail fail here, before the division algorithm runs.
    /// </summary>
    private static bool SpansAllow(Scalar b, Scalar s)
    {
        foreach (var atom in s.FactorAtoms)
        {
            var (sLow, sHigh) = Powers(s, atom);
            if (sHigh == sLow) continue;
            var (bLow, bHigh) = Powers(b, atom);
            if (bHigh - bLow < sHigh - sLow) return false;
        }
        return true;
    }

    private static (int Low, int High) Powers(Scalar e, Atom atom)
    {
        int low = int.MaxValue, high = int.MinValue;
        foreach (var t in e.TermArray)
        {
            var p = t.Monomial.PowerOf(atom);
            low = Math.Min(low, p);
            high = Math.Max(high, p);
        }
        return (low, high);
    }

    /// <summary>m / d when every power of d is at most m's (as exponents may be negative, compare signed).</summary>
    private static Monomial? Divide(Monomial m, Monomial d) => Monomial.TryDivide(m, d);
}
