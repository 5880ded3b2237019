using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// A vector-space basis with named basis vectors and a metric: the home of every multivector.
/// Blades are named by their basis vectors joined with '^' (e.g. "e1^e2"); the scalar blade is "1".
/// </summary>
public sealed class Frame
{
    public const int MaxDimension = 16;

    private readonly Dictionary<string, int> _indexByName;
    private readonly string[] _names;

    public string Name { get; }
    public IReadOnlyList<string> BasisVectorNames => _names;
    public Metric Metric { get; }
    public int Dimension => _names.Length;
    public int BladeCount => 1 << Dimension;
    public BasisBlade Pseudoscalar => new(BladeCount - 1);

    internal BladeProductTable Products { get; }

    /// <summary>Table-free products for orthonormal (and null) bases; null for other metrics.</summary>
    internal SignatureProducts? SignatureProducts { get; }

    public Frame(string name, IReadOnlyList<string> basisVectorNames, Metric metric)
    {
        Name = name;
        if (basisVectorNames.Count != metric.Dimension)
            throw new AlgebraException(name, $"{basisVectorNames.Count} basis vector names were given for a metric of dimension {metric.Dimension}.");
        if (basisVectorNames.Count > MaxDimension)
            throw new AlgebraException(name, $"{basisVectorNames.Count} basis vectors are too many; at most {MaxDimension} are supported.");
        _names = basisVectorNames.ToArray();
        _indexByName = new Dictionary<string, int>(StringComparer.Ordinal);
        for (var i = 0; i < _names.Length; i++)
        {
            var n = _names[i];
            if (string.IsNullOrWhiteSpace(n) || n.Contains('^') || n == "1")
                throw new AlgebraException(name, $"'{n}' cannot name a basis vector.");
            if (!_indexByName.TryAdd(n, i))
                throw new AlgebraException(name, $"the basis vector name '{n}' is used twice.");
        }
        Metric = metric;
        Products = new BladeProductTable(metric);
        SignatureProducts = SignatureProducts.For(metric);
    }

    /// <summary>A Euclidean frame e1 … en.</summary>
    public static Frame Euclidean(string name, int n) =>
        new(name, Enumerable.Range(1, n).Select(i => $"e{i}").ToArray(), Metric.Euclidean(n, name));

    /// <summary>A frame of signature (p, q, r) named e1 … e(p+q+r) unless names are given.</summary>
    public static Frame FromSignature(string name, int p, int q, int r = 0, IReadOnlyList<string>? names = null) =>
        new(name, names ?? Enumerable.Range(1, p + q + r).Select(i => $"e{i}").ToArray(), Metric.FromSignature(p, q, r, name));

    /// <summary>The 5D conformal frame no, e1, e2, e3, ni with no·ni = −1 (thesis §3.6).</summary>
    public static Frame Conformal3D(string name = "cga5d")
    {
        var g = new Rational[5, 5];
        for (var i = 0; i < 5; i++)
        for (var j = 0; j < 5; j++)
            g[i, j] = Rational.Zero;
        g[1, 1] = g[2, 2] = g[3, 3] = Rational.One;
        g[0, 4] = g[4, 0] = Rational.MinusOne;
        return new Frame(name, ["no", "e1", "e2", "e3", "ni"], Metric.FromMatrix(g, name));
    }

    public int IndexOf(string basisVectorName) =>
        _indexByName.TryGetValue(basisVectorName, out var i)
            ? i
            : throw new AlgebraException(Name, $"there is no basis vector named '{basisVectorName}'.");

    public bool TryGetIndex(string basisVectorName, out int index) => _indexByName.TryGetValue(basisVectorName, out index);

    public string BladeName(BasisBlade blade)
    {
        if (blade.Id == 0) return "1";
        return string.Join("^", blade.BasisVectorIndices().Select(i => _names[i]));
    }

    /// <summary>
    /// Reads a blade name such as "e2^e1" (any order: the sign says how it relates to the
    /// canonical blade e1^e2) or "1". A repeated basis vector makes the name invalid.
    /// </summary>
    public bool TryParseBlade(string text, out BasisBlade blade, out int sign)
    {
        blade = BasisBlade.Scalar;
        sign = 1;
        text = text.Trim();
        if (text == "1") return true;
        var id = 0;
        foreach (var part in text.Split('^'))
        {
            if (!_indexByName.TryGetValue(part.Trim(), out var i)) return false;
            var bit = 1 << i;
            if ((id & bit) != 0) return false;
            sign *= BasisBlade.OuterSign(id, bit);
            id |= bit;
        }
        blade = new BasisBlade(id);
        return true;
    }

    public BasisBlade ParseBlade(string text, out int sign)
    {
        // Code that reads coefficients by name (m["e1^e2"]) asks for the same few names again and again.
        if (_parsedBlades.TryGetValue(text, out var known))
        {
            sign = known.Sign;
            return known.Blade;
        }
        if (!TryParseBlade(text, out var blade, out sign))
            throw new AlgebraException(Name, $"'{text}' does not name a basis blade (basis vectors: {string.Join(", ", _names)}).");
        if (_parsedBlades.Count < MaxParsedBlades) _parsedBlades.TryAdd(text, (blade, sign));
        return blade;
    }

    private const int MaxParsedBlades = 4096;
    private readonly System.Collections.Concurrent.ConcurrentDictionary<string, (BasisBlade Blade, int Sign)> _parsedBlades = new(StringComparer.Ordinal);

    /// <summary>All blades of grade k, in ascending id order.</summary>
    public IEnumerable<BasisBlade> BladesOfGrade(int k)
    {
        for (var id = 0; id < BladeCount; id++)
            if (BitOperations.PopCount((uint)id) == k) yield return new BasisBlade(id);
    }

    /// <summary>The exact product of two basis blades as a list of signed blades.</summary>
    public IReadOnlyList<BladeTerm> BladeProduct(ProductKind kind, BasisBlade a, BasisBlade b)
    {
        CheckBlade(a);
        CheckBlade(b);
        return Products.Product(kind, a.Id, b.Id);
    }

    internal void CheckBlade(BasisBlade b)
    {
        if (b.Id < 0 || b.Id >= BladeCount)
            throw new AlgebraException(Name, $"blade id {b.Id} is outside this {Dimension}-dimensional frame.");
    }

    public override string ToString() => Name;
}
