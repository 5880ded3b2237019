using GMac.Core.Algebra;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// An immutable symbolic real scalar in canonical form: a sum of terms coefficient × monomial with
/// exact rational coefficients, terms sorted by monomial, like terms combined and zero terms dropped.
/// Scalars are hash-consed: structurally equal expressions are the same object, so reference
/// equality is equality and hashing is O(1).
/// </summary>
public sealed partial class Scalar : IComparable<Scalar>
{
    private static readonly WeakInternTable<Scalar> Table = new(new StructuralComparer());

    public static Scalar Zero { get; } = Intern([]);
    public static Scalar One { get; } = Intern([new Term(Rational.One, Monomial.One)]);
    public static Scalar NegativeOne { get; } = Intern([new Term(Rational.MinusOne, Monomial.One)]);

    // Every static scalar lives in this file: initializers in other partial files have no defined
    // order relative to the intern table above.
    public static Scalar Pi { get; } = Atom.Create(AtomKind.Pi, "pi").AsScalar();

    private readonly Term[] _terms;
    private readonly int _hash;
    private IReadOnlySet<string>? _variables;
    private IReadOnlySet<Atom>? _atoms;
    private IReadOnlySet<Atom>? _factorAtoms;

    private object? _fingerprint; // a boxed UInt128: a reference is published whole, a UInt128 field could tear

    /// <summary>A digest of the canonical structure, stable across runs (see <see cref="StructuralFingerprint"/>).</summary>
    internal UInt128 Fingerprint => (UInt128)(_fingerprint ??= StructuralFingerprint.Of(this));

    private Scalar(Term[] terms)
    {
        _terms = terms;
        _hash = HashOf(terms);
    }

    private static int HashOf(ReadOnlySpan<Term> terms)
    {
        var hash = new HashCode();
        foreach (var term in terms)
        {
            hash.Add(term.Coefficient);
            hash.Add(term.Monomial.GetHashCode());
        }
        return hash.ToHashCode();
    }

    /// <summary>The terms in canonical order (the constant term, if any, first).</summary>
    public IReadOnlyList<Term> Terms => _terms;

    internal Term[] TermArray => _terms;

    public bool IsConstant => _terms.Length == 0 || (_terms.Length == 1 && _terms[0].Monomial.IsOne);

    /// <summary>True for a single term c·m; such scalars have an exact reciprocal without an inverse atom.</summary>
    public bool IsMonomial => _terms.Length <= 1;

    public bool TryGetConstant(out Rational value)
    {
        if (_terms.Length == 0)
        {
            value = Rational.Zero;
            return true;
        }
        if (_terms.Length == 1 && _terms[0].Monomial.IsOne)
        {
            value = _terms[0].Coefficient;
            return true;
        }
        value = Rational.Zero;
        return false;
    }

    public static Scalar Constant(Rational value) =>
        value.IsZero ? Zero : value.IsOne ? One : InternTerm(new Term(value, Monomial.One));

    public static Scalar Variable(string name)
    {
        if (!ScalarParser.IsIdentifier(name) || name == "pi")
            throw new ArgumentException($"'{name}' is not a valid variable name: use letters, digits, '_' and '.', starting with a letter or '_' (and not 'pi').", nameof(name));
        return Atom.Create(AtomKind.Variable, name).AsScalar();
    }

    public static implicit operator Scalar(int value) => Constant(value);
    public static implicit operator Scalar(Rational value) => Constant(value);

    internal static Scalar FromAtom(Atom atom) => Intern([new Term(Rational.One, Monomial.FromAtom(atom, 1))]);

    /// <summary>Builds a scalar from terms in any order: sorts, combines like terms, drops zeros.</summary>
    public static Scalar FromTerms(IEnumerable<Term> terms)
    {
        var list = new List<Term>(terms);
        return FromUnsorted(list);
    }

    /// <summary>As <see cref="FromTerms"/>, for a list the caller gives away: it is sorted in place, not copied.</summary>
    internal static Scalar FromOwnedTerms(List<Term> terms) => FromUnsorted(terms);

    public static Scalar FromTerm(Rational coefficient, Monomial monomial) =>
        coefficient.IsZero ? Zero : InternTerm(new Term(coefficient, monomial));

    private static Scalar FromUnsorted(List<Term> list)
    {
        if (list.Count == 0) return Zero;
        list.Sort(static (x, y) => Monomial.Compare(x.Monomial, y.Monomial));
        var result = Scratch(list.Count);
        var k = 0;
        var current = list[0];
        for (var i = 1; i < list.Count; i++)
        {
            var next = list[i];
            if (ReferenceEquals(next.Monomial, current.Monomial))
            {
                current = new Term(current.Coefficient + next.Coefficient, current.Monomial);
                continue;
            }
            if (!current.Coefficient.IsZero) result[k++] = current;
            current = next;
        }
        if (!current.Coefficient.IsZero) result[k++] = current;
        return InternScratch(result, k);
    }

    private static Scalar Intern(Term[] terms)
    {
        var candidate = new Scalar(terms);
        return Table.GetOrAdd(candidate);
    }

    // Sums, differences and scaled copies are built in a per-thread buffer and looked up from
    // there: most of them already exist, and then neither the terms nor the scalar are allocated.
    [ThreadStatic] private static Term[]? _scratch;

    private static Term[] Scratch(int length)
    {
        var buffer = _scratch;
        if (buffer is null || buffer.Length < length) _scratch = buffer = new Term[Math.Max(length, 2 * (buffer?.Length ?? 32))];
        return buffer;
    }

    /// <summary>The scalar of the first <paramref name="count"/> terms of <see cref="_scratch"/>, which is then cleared.</summary>
    private static Scalar InternScratch(Term[] buffer, int count)
    {
        var scalar = count == 0 ? Zero : Table.GetOrAdd(HashOf(buffer.AsSpan(0, count)), new ScratchTerms(buffer, count));
        Array.Clear(buffer, 0, count); // hold no monomial alive past this call
        return scalar;
    }

    /// <summary>The scalar of one non-zero term.</summary>
    private static Scalar InternTerm(Term term)
    {
        var buffer = Scratch(1);
        buffer[0] = term;
        return InternScratch(buffer, 1);
    }

    private readonly struct ScratchTerms(Term[] buffer, int count) : IInternKey<Scalar>
    {
        public bool Describes(Scalar candidate)
        {
            var terms = candidate._terms;
            if (terms.Length != count) return false;
            for (var i = 0; i < count; i++)
                if (!ReferenceEquals(terms[i].Monomial, buffer[i].Monomial) || terms[i].Coefficient != buffer[i].Coefficient)
                    return false;
            return true;
        }

        public Scalar Create() => new(buffer.AsSpan(0, count).ToArray());
    }

    /// <summary>Entries in the scalar intern table (live scalars plus dead ones not yet swept).</summary>
    internal static int InternedCount => Table.Count;

    public override int GetHashCode() => _hash;

    public override bool Equals(object? obj) => ReferenceEquals(this, obj);

    public bool Equals(Scalar? other) => ReferenceEquals(this, other);

    public static bool operator ==(Scalar? a, Scalar? b) => ReferenceEquals(a, b);
    public static bool operator !=(Scalar? a, Scalar? b) => !ReferenceEquals(a, b);

    /// <summary>The canonical structural order; it is not the numeric order.</summary>
    public int CompareTo(Scalar? other) => other is null ? 1 : CompareStructurally(this, other);

    internal static int CompareStructurally(Scalar a, Scalar b)
    {
        if (ReferenceEquals(a, b)) return 0;
        var x = a._terms;
        var y = b._terms;
        var n = Math.Min(x.Length, y.Length);
        for (var i = 0; i < n; i++)
        {
            var c = Monomial.Compare(x[i].Monomial, y[i].Monomial);
            if (c != 0) return c;
            c = x[i].Coefficient.CompareTo(y[i].Coefficient);
            if (c != 0) return c;
        }
        return x.Length.CompareTo(y.Length);
    }

    // ---- ring operations ------------------------------------------------------------------

    public static Scalar operator +(Scalar a, Scalar b) => Merge(a, b, negateRight: false);

    public static Scalar operator -(Scalar a, Scalar b) => Merge(a, b, negateRight: true);

    public static Scalar operator -(Scalar a) => a._terms.Length == 0 ? a : Scale(a, Rational.MinusOne);

    public static Scalar operator +(Scalar a) => a;

    public static Scalar operator *(Scalar a, Scalar b)
    {
        var x = a._terms;
        var y = b._terms;
        if (x.Length == 0 || y.Length == 0) return Zero;
        if (a.TryGetConstant(out var ca)) return Scale(b, ca);
        if (b.TryGetConstant(out var cb)) return Scale(a, cb);
        if (x.Length == 1 && y.Length == 1)
            return InternTerm(new Term(x[0].Coefficient * y[0].Coefficient, x[0].Monomial * y[0].Monomial));
        if ((long)x.Length * y.Length > MaxProductPairs) throw TooLarge($"a product of {x.Length} terms by {y.Length} terms needs {(long)x.Length * y.Length} term products, more than the limit of {MaxProductPairs}");
        // Accumulate by monomial (reference keys, cached hashes), then sort once. The table and
        // list are reused per thread: products are the engine's most frequent operation, and
        // fresh ones were a large share of everything it allocated.
        var sums = _productSums ?? new Dictionary<Monomial, Rational>();
        var list = _productTerms ?? new List<Term>();
        _productSums = null; // a product computed while this one runs (none today) gets its own
        _productTerms = null;
        try
        {
            foreach (var s in x)
            {
                foreach (var t in y)
                {
                    var m = s.Monomial * t.Monomial;
                    var c = s.Coefficient * t.Coefficient;
                    sums[m] = sums.TryGetValue(m, out var previous) ? previous + c : c;
                }
                // Checked per row, as the product grows: terms that cancel later are rare in expansions.
                if (sums.Count > MaxTerms) throw TooLarge($"a product of {x.Length} terms by {y.Length} terms has more than {MaxTerms} terms, the limit");
            }
            foreach (var (m, c) in sums)
                if (!c.IsZero) list.Add(new Term(c, m));
            return FromUnsorted(list);
        }
        finally
        {
            // Clear costs the table's capacity: one grown by a rare huge product is not kept
            if (sums.EnsureCapacity(0) <= MaxPooledProductTerms)
            {
                sums.Clear();
                list.Clear();
                _productSums = sums;
                _productTerms = list;
            }
        }
    }

    /// <summary>
    /// Most terms a scalar may have. Expanding products (a polynomial to a high power) grows terms
    /// combinatorially and every later stage costs at least as much again; the library's largest
    /// scalar has about 6,600 terms. Exceeding it is refused as too large, a positioned diagnostic.
    /// </summary>
    public const int MaxTerms = 1 << 14;

    /// <summary>Most term-by-term multiplications of one product: bounds its time before it starts.</summary>
    public const long MaxProductPairs = 1L << 22;

    private static AlgebraException TooLarge(string message) =>
        new(null, $"{message}; the expression is too large to expand symbolically (restructure it, e.g. name repeated factors)") { ExceedsLimit = true };

    private const int MaxPooledProductTerms = 1024;
    [ThreadStatic] private static Dictionary<Monomial, Rational>? _productSums;
    [ThreadStatic] private static List<Term>? _productTerms;

    public static Scalar operator /(Scalar a, Scalar b) => a * Reciprocal(b);

    public static Scalar operator ++(Scalar a) => a + One;

    public static Scalar operator --(Scalar a) => a - One;

    public static Scalar Scale(Scalar a, Rational factor)
    {
        if (factor.IsZero || a._terms.Length == 0) return Zero;
        if (factor.IsOne) return a;
        var x = a._terms;
        var result = Scratch(x.Length);
        for (var i = 0; i < x.Length; i++) result[i] = new Term(x[i].Coefficient * factor, x[i].Monomial);
        return InternScratch(result, x.Length);
    }

    private static Scalar Merge(Scalar a, Scalar b, bool negateRight)
    {
        var x = a._terms;
        var y = b._terms;
        if (y.Length == 0) return a;
        if (x.Length == 0) return negateRight ? -b : b;
        var result = Scratch(x.Length + y.Length);
        int i = 0, j = 0, k = 0;
        while (i < x.Length && j < y.Length)
        {
            var c = Monomial.Compare(x[i].Monomial, y[j].Monomial);
            if (c < 0) result[k++] = x[i++];
            else if (c > 0)
            {
                result[k++] = negateRight ? new Term(-y[j].Coefficient, y[j].Monomial) : y[j];
                j++;
            }
            else
            {
                var sum = negateRight ? x[i].Coefficient - y[j].Coefficient : x[i].Coefficient + y[j].Coefficient;
                if (!sum.IsZero) result[k++] = new Term(sum, x[i].Monomial);
                i++;
                j++;
            }
        }
        while (i < x.Length) result[k++] = x[i++];
        for (; j < y.Length; j++) result[k++] = negateRight ? new Term(-y[j].Coefficient, y[j].Monomial) : y[j];
        if (k > MaxTerms)
        {
            Array.Clear(result, 0, k);
            throw TooLarge($"a sum of {x.Length} terms and {y.Length} terms has {k} terms, more than the limit of {MaxTerms}");
        }
        return InternScratch(result, k);
    }

    /// <summary>1/a: exact for constants and single terms, an inverse atom for sums.</summary>
    public static Scalar Reciprocal(Scalar a)
    {
        var x = a._terms;
        if (x.Length == 0) throw new DivideByZeroException("Division of a symbolic scalar by zero.");
        if (x.Length == 1)
        {
            var coefficient = x[0].Coefficient.Reciprocal();
            var factors = x[0].Monomial.FactorArray;
            var inverted = new List<Factor>(factors.Length);
            var restored = One;
            foreach (var factor in factors)
            {
                if (factor.Atom.Kind == AtomKind.Inverse)
                    restored *= IntegerPower(factor.Atom.ArgumentArray[0], factor.Power);
                else
                    inverted.Add(new Factor(factor.Atom, -factor.Power));
            }
            return Scale(restored, coefficient) * FromTerm(Rational.One, Monomial.Intern([.. inverted]));
        }
        // Normalize so the leading coefficient is 1: 1/(c·s) = (1/c)·inv(s).
        var lead = x[0].Coefficient;
        var normalized = Scale(a, lead.Reciprocal());
        return Scale(Atom.Create(AtomKind.Inverse, "inv", normalized).AsScalar(), lead.Reciprocal());
    }

    /// <summary>a^n for an integer n (0^0 = 1 as in Math.Pow); a sum is expanded.</summary>
    public static Scalar IntegerPower(Scalar a, int n)
    {
        if (n == 0) return One;
        if (n < 0) return IntegerPower(Reciprocal(a), -n);
        if (n == 1) return a;
        var x = a._terms;
        if (x.Length == 0) return Zero;
        if (x.Length == 1)
        {
            var factors = x[0].Monomial.FactorArray;
            var powered = new Factor[factors.Length];
            for (var i = 0; i < factors.Length; i++) powered[i] = new Factor(factors[i].Atom, checked(factors[i].Power * n));
            return FromTerm(x[0].Coefficient.Pow(n), Monomial.Intern(powered));
        }
        var result = One;
        var square = a;
        while (true)
        {
            if ((n & 1) != 0) result *= square;
            n >>= 1;
            if (n == 0) return result;
            square *= square;
        }
    }

    /// <summary>Every variable name occurring anywhere in the expression, including inside function arguments.</summary>
    public IReadOnlySet<string> Variables => _variables ??= CollectVariables();

    private HashSet<string> CollectVariables()
    {
        var names = new HashSet<string>(StringComparer.Ordinal);
        foreach (var term in _terms)
        foreach (var factor in term.Monomial.FactorArray)
        {
            if (factor.Atom.Kind == AtomKind.Variable) names.Add(factor.Atom.Name);
            foreach (var argument in factor.Atom.ArgumentArray) names.UnionWith(argument.Variables);
        }
        return names;
    }

    /// <summary>Every distinct atom occurring in the expression, arguments included (each once).</summary>
    public IReadOnlySet<Atom> Atoms() => _atoms ??= CollectAtoms();

    /// <summary>The distinct atoms of the terms' own factors, not looking inside function arguments.</summary>
    internal IReadOnlySet<Atom> FactorAtoms => _factorAtoms ??= CollectFactorAtoms();

    private HashSet<Atom> CollectFactorAtoms()
    {
        var atoms = new HashSet<Atom>();
        foreach (var term in _terms)
        foreach (var factor in term.Monomial.FactorArray)
            atoms.Add(factor.Atom);
        return atoms;
    }

    private HashSet<Atom> CollectAtoms()
    {
        var atoms = new HashSet<Atom>();
        var pending = new Stack<Scalar>();
        pending.Push(this);
        while (pending.Count > 0)
        {
            foreach (var term in pending.Pop()._terms)
            foreach (var factor in term.Monomial.FactorArray)
                if (atoms.Add(factor.Atom))
                    foreach (var argument in factor.Atom.ArgumentArray) pending.Push(argument);
        }
        return atoms;
    }

    public override string ToString() => ScalarPrinter.Format(this);

    private sealed class StructuralComparer : IEqualityComparer<Scalar>
    {
        public bool Equals(Scalar? a, Scalar? b)
        {
            if (ReferenceEquals(a, b)) return true;
            if (a is null || b is null || a._hash != b._hash || a._terms.Length != b._terms.Length) return false;
            for (var i = 0; i < a._terms.Length; i++)
                if (!ReferenceEquals(a._terms[i].Monomial, b._terms[i].Monomial) || a._terms[i].Coefficient != b._terms[i].Coefficient)
                    return false;
            return true;
        }

        public int GetHashCode(Scalar scalar) => scalar._hash;
    }
}
