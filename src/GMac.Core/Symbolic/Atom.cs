namespace GMac.Core.Symbolic;

/// <summary>
/// An indivisible factor of a monomial: a variable, the constant pi, or a function of scalars.
/// Atoms are interned, so two equal atoms are the same object and compare by reference.
/// Create them through <see cref="Scalar"/> (Variable, Sin, Sqrt, ...), which also folds constants.
/// </summary>
public sealed class Atom : IComparable<Atom>
{
    private static readonly WeakInternTable<Atom> Table = new(new StructuralComparer());

    private readonly Scalar[] _arguments;
    private readonly int _hash;
    private Scalar? _asScalar;

    private object? _fingerprint; // a boxed UInt128: a reference is published whole, a UInt128 field could tear

    /// <summary>A digest of the canonical structure, stable across runs (see <see cref="StructuralFingerprint"/>).</summary>
    internal UInt128 Fingerprint => (UInt128)(_fingerprint ??= StructuralFingerprint.Of(this));

    private Atom(AtomKind kind, string name, Scalar[] arguments)
    {
        Kind = kind;
        Name = name;
        _arguments = arguments;
        var hash = new HashCode();
        hash.Add((int)kind);
        hash.Add(name);
        foreach (var argument in arguments) hash.Add(argument.GetHashCode());
        _hash = hash.ToHashCode();
    }

    public AtomKind Kind { get; }

    /// <summary>The variable name, or the function name as written in text ("sin", "atan2", "pi", "inv").</summary>
    public string Name { get; }

    public IReadOnlyList<Scalar> Arguments => _arguments;

    internal Scalar[] ArgumentArray => _arguments;

    /// <summary>This atom as a scalar expression (coefficient 1, power 1).</summary>
    public Scalar AsScalar() => _asScalar ??= Scalar.FromAtom(this);

    internal static Atom Create(AtomKind kind, string name, params Scalar[] arguments)
    {
        var candidate = new Atom(kind, name, arguments);
        return Table.GetOrAdd(candidate);
    }

    public override int GetHashCode() => _hash;

    public override string ToString() => ScalarPrinter.FormatAtom(this);

    public int CompareTo(Atom? other) => other is null ? 1 : Compare(this, other);

    /// <summary>The canonical order: by kind, then name, then arguments. Independent of creation order.</summary>
    internal static int Compare(Atom a, Atom b)
    {
        if (ReferenceEquals(a, b)) return 0;
        if (a.Kind != b.Kind) return a.Kind < b.Kind ? -1 : 1;
        var byName = string.CompareOrdinal(a.Name, b.Name);
        if (byName != 0) return byName;
        var x = a._arguments;
        var y = b._arguments;
        for (var i = 0; i < x.Length && i < y.Length; i++)
        {
            var c = Scalar.CompareStructurally(x[i], y[i]);
            if (c != 0) return c;
        }
        return x.Length.CompareTo(y.Length);
    }

    private sealed class StructuralComparer : IEqualityComparer<Atom>
    {
        public bool Equals(Atom? a, Atom? b)
        {
            if (ReferenceEquals(a, b)) return true;
            if (a is null || b is null || a._hash != b._hash || a.Kind != b.Kind || a.Name != b.Name) return false;
            if (a._arguments.Length != b._arguments.Length) return false;
            for (var i = 0; i < a._arguments.Length; i++)
                if (!ReferenceEquals(a._arguments[i], b._arguments[i])) return false;
            return true;
        }

        public int GetHashCode(Atom atom) => atom._hash;
    }
}
