namespace GMac.Core.Symbolic;

/// <summary>
/// A product of atoms raised to non-zero integer powers, atoms in canonical order and each at
/// most once. Interned: equal monomials are the same object. The empty product is <see cref="One"/>.
/// Inverse atoms only ever carry positive powers (their negative powers are the sums themselves).
/// </summary>
public sealed class Monomial : IComparable<Monomial>
{
    private static readonly WeakInternTable<Monomial> Table = new(new StructuralComparer());

    public static readonly Monomial One = Intern([]);

    private readonly Factor[] _factors;
    private readonly int _hash;

    private object? _fingerprint; // a boxed UInt128: a reference is published whole, a UInt128 field could tear

    /// <summary>A digest of the canonical structure, stable across runs (see <see cref="StructuralFingerprint"/>).</summary>
    internal UInt128 Fingerprint => (UInt128)(_fingerprint ??= StructuralFingerprint.Of(this));

    private Monomial(Factor[] factors)
    {
        _factors = factors;
        _hash = HashOf(factors);
    }

    private static int HashOf(ReadOnlySpan<Factor> factors)
    {
        var hash = new HashCode();
        foreach (var factor in factors)
        {
            hash.Add(factor.Atom.GetHashCode());
            hash.Add(factor.Power);
        }
        return hash.ToHashCode();
    }

    public IReadOnlyList<Factor> Factors => _factors;

    internal Factor[] FactorArray => _factors;

    public int Count => _factors.Length;

    public bool IsOne => _factors.Length == 0;

    /// <summary>Interns a monomial from factors already in canonical order with non-zero powers.</summary>
    internal static Monomial Intern(Factor[] factors)
    {
        var candidate = new Monomial(factors);
        return Table.GetOrAdd(candidate);
    }

    internal static Monomial FromAtom(Atom atom, int power) => Intern([new Factor(atom, power)]);

    /// <summary>Builds a monomial from factors in any order; repeated atoms are merged.</summary>
    public static Monomial Create(IEnumerable<Factor> factors)
    {
        var list = new List<Factor>(factors);
        list.Sort((x, y) => Atom.Compare(x.Atom, y.Atom));
        var merged = new List<Factor>(list.Count);
        foreach (var factor in list)
        {
            if (factor.Atom.Kind == AtomKind.Inverse && factor.Power < 0)
                throw new ArgumentException("An inverse atom cannot carry a negative power; use the sum itself.", nameof(factors));
            if (merged.Count > 0 && ReferenceEquals(merged[^1].Atom, factor.Atom))
                merged[^1] = factor with { Power = merged[^1].Power + factor.Power };
            else
                merged.Add(factor);
        }
        merged.RemoveAll(f => f.Power == 0);
        return Intern([.. merged]);
    }

    /// <summary>The product of two monomials by a merge of their sorted factor lists.</summary>
    public static Monomial operator *(Monomial a, Monomial b)
    {
        if (a._factors.Length == 0) return b;
        if (b._factors.Length == 0) return a;
        var x = a._factors;
        var y = b._factors;
        // Merged into a per-thread buffer: most products already exist, and then nothing is allocated.
        var result = Scratch(x.Length + y.Length);
        int i = 0, j = 0, k = 0;
        while (i < x.Length && j < y.Length)
        {
            var c = Atom.Compare(x[i].Atom, y[j].Atom);
            if (c < 0) result[k++] = x[i++];
            else if (c > 0) result[k++] = y[j++];
            else
            {
                var power = x[i].Power + y[j].Power;
                if (power != 0) result[k++] = new Factor(x[i].Atom, power);
                i++;
                j++;
            }
        }
        while (i < x.Length) result[k++] = x[i++];
        while (j < y.Length) result[k++] = y[j++];
        return InternScratch(result, k);
    }

    [ThreadStatic] private static Factor[]? _productFactors;

    private static Factor[] Scratch(int length)
    {
        var buffer = _productFactors;
        if (buffer is null || buffer.Length < length) _productFactors = buffer = new Factor[Math.Max(16, length)];
        return buffer;
    }

    /// <summary>The power of <paramref name="atom"/> in the monomial, 0 when it is absent.</summary>
    internal int PowerOf(Atom atom)
    {
        foreach (var factor in _factors)
            if (ReferenceEquals(factor.Atom, atom)) return factor.Power;
        return 0;
    }

    /// <summary>m with the power of <paramref name="atom"/> set to <paramref name="power"/> (0 removes the atom).</summary>
    internal static Monomial WithPower(Monomial m, Atom atom, int power)
    {
        if (atom.Kind == AtomKind.Inverse && power < 0)
            throw new ArgumentException("An inverse atom cannot carry a negative power; use the sum itself.", nameof(power));
        var x = m._factors;
        var result = Scratch(x.Length + 1);
        var k = 0;
        var placed = power == 0;
        foreach (var factor in x)
        {
            if (ReferenceEquals(factor.Atom, atom)) continue;
            if (!placed && Atom.Compare(atom, factor.Atom) < 0)
            {
                result[k++] = new Factor(atom, power);
                placed = true;
            }
            result[k++] = factor;
        }
        if (!placed) result[k++] = new Factor(atom, power);
        return InternScratch(result, k);
    }

    /// <summary>The monomial of the first <paramref name="count"/> factors of the scratch buffer: made only when no equal one lives.</summary>
    private static Monomial InternScratch(Factor[] buffer, int count) => Table.GetOrAdd(HashOf(buffer.AsSpan(0, count)), new ScratchFactors(buffer, count));

    /// <summary>The first <c>Count</c> factors of a scratch buffer, as the key of the monomial they make.</summary>
    private readonly struct ScratchFactors(Factor[] buffer, int count) : IInternKey<Monomial>
    {
        public bool Describes(Monomial candidate) => candidate._factors.AsSpan().SequenceEqual(buffer.AsSpan(0, count));

        public Monomial Create() => new(buffer.AsSpan(0, count).ToArray());
    }

    /// <summary>The quotient m / divisor when divisor divides m (same-signed powers no larger in size), else null.</summary>
    internal static Monomial? TryDivide(Monomial m, Monomial divisor)
    {
        var x = m._factors;
        var y = divisor._factors;
        var result = Scratch(x.Length);
        var k = 0;
        var j = 0;
        foreach (var factor in x)
        {
            if (j < y.Length && ReferenceEquals(factor.Atom, y[j].Atom))
            {
                var d = y[j].Power;
                if (Math.Sign(d) != Math.Sign(factor.Power) || Math.Abs(d) > Math.Abs(factor.Power)) return null;
                if (factor.Power != d) result[k++] = factor with { Power = factor.Power - d };
                j++;
            }
            else
            {
                if (j < y.Length && Atom.Compare(y[j].Atom, factor.Atom) < 0) return null;
                result[k++] = factor;
            }
        }
        return j == y.Length ? InternScratch(result, k) : null;
    }

    public override int GetHashCode() => _hash;

    public override string ToString() => ScalarPrinter.FormatTerm(new Term(Numerics.Rational.One, this), first: true);

    public int CompareTo(Monomial? other) => other is null ? 1 : Compare(this, other);

    /// <summary>
    /// The canonical order of terms: lexicographic over factors (atom order, then higher power first),
    /// a proper prefix first, so the constant term leads.
    /// </summary>
    internal static int Compare(Monomial a, Monomial b)
    {
        if (ReferenceEquals(a, b)) return 0;
        var x = a._factors;
        var y = b._factors;
        var n = Math.Min(x.Length, y.Length);
        for (var i = 0; i < n; i++)
        {
            var c = Atom.Compare(x[i].Atom, y[i].Atom);
            if (c != 0) return c;
            if (x[i].Power != y[i].Power) return x[i].Power > y[i].Power ? -1 : 1;
        }
        return x.Length.CompareTo(y.Length);
    }

    private sealed class StructuralComparer : IEqualityComparer<Monomial>
    {
        public bool Equals(Monomial? a, Monomial? b)
        {
            if (ReferenceEquals(a, b)) return true;
            if (a is null || b is null || a._hash != b._hash || a._factors.Length != b._factors.Length) return false;
            for (var i = 0; i < a._factors.Length; i++)
                if (!ReferenceEquals(a._factors[i].Atom, b._factors[i].Atom) || a._factors[i].Power != b._factors[i].Power)
                    return false;
            return true;
        }

        public int GetHashCode(Monomial monomial) => monomial._hash;
    }
}
