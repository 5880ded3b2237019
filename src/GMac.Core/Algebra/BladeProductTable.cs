using System.Collections.Concurrent;
using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// Exact products of basis blades for one frame, straight from its bilinear form. Every entry is
/// computed once and kept. For a diagonal metric a product is one signed blade; for a general
/// metric the outer-product basis is multiplied with Chevalley's recursion:
/// e_i X = e_i ⌋ X + e_i ∧ X, and e_A = e_i ∧ e_A' = e_i e_A' − e_i ⌋ e_A' (i the lowest index of A).
/// </summary>
internal sealed class BladeProductTable
{
    private readonly Metric _metric;
    private readonly int _n;
    private readonly ConcurrentDictionary<long, BladeTerm[]>[] _cache;

    public BladeProductTable(Metric metric)
    {
        _metric = metric;
        _n = metric.Dimension;
        _cache = new ConcurrentDictionary<long, BladeTerm[]>[Enum.GetValues<ProductKind>().Length];
        for (var i = 0; i < _cache.Length; i++) _cache[i] = new ConcurrentDictionary<long, BladeTerm[]>();
    }

    private static long Key(int a, int b) => ((long)a << 32) | (uint)b;

    public BladeTerm[] Product(ProductKind kind, int a, int b) =>
        _cache[(int)kind].GetOrAdd(Key(a, b), _ => Compute(kind, a, b));

    private BladeTerm[] Compute(ProductKind kind, int a, int b)
    {
        if (kind == ProductKind.Geometric) return ComputeGeometric(a, b);
        var ga = BitOperations.PopCount((uint)a);
        var gb = BitOperations.PopCount((uint)b);
        switch (kind)
        {
            case ProductKind.Commutator:
            case ProductKind.AntiCommutator:
            {
                var sign = kind == ProductKind.Commutator ? Rational.MinusOne : Rational.One;
                var sum = new Dictionary<int, Rational>();
                Accumulate(sum, Product(ProductKind.Geometric, a, b), new Rational(1, 2));
                Accumulate(sum, Product(ProductKind.Geometric, b, a), sign * new Rational(1, 2));
                return ToTerms(sum);
            }
            default:
            {
                var grade = kind switch
                {
                    ProductKind.Outer => ga + gb,
                    ProductKind.LeftContraction => gb - ga,
                    ProductKind.RightContraction => ga - gb,
                    ProductKind.Scalar => 0,
                    ProductKind.FatDot => Math.Abs(gb - ga),
                    ProductKind.HestenesInner => ga == 0 || gb == 0 ? -1 : Math.Abs(gb - ga),
                    _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown product."),
                };
                if (grade < 0) return [];
                // The outer product is metric-free; the shortcut also keeps degenerate frames exact.
                if (kind == ProductKind.Outer)
                    return (a & b) != 0 ? [] : [new BladeTerm(a | b, BasisBlade.OuterSign(a, b))];
                return Product(ProductKind.Geometric, a, b)
                    .Where(t => BitOperations.PopCount((uint)t.Blade) == grade)
                    .ToArray();
            }
        }
    }

    private BladeTerm[] ComputeGeometric(int a, int b)
    {
        if (_metric.IsDiagonal)
        {
            Rational coefficient = BasisBlade.OuterSign(a, b);
            for (var common = a & b; common != 0; common &= common - 1)
                coefficient *= _metric[BitOperations.TrailingZeroCount(common), BitOperations.TrailingZeroCount(common)];
            return coefficient.IsZero ? [] : [new BladeTerm(a ^ b, coefficient)];
        }

        if (a == 0) return [new BladeTerm(b, Rational.One)];
        var i = BitOperations.TrailingZeroCount(a);
        var rest = a & (a - 1);
        var sum = new Dictionary<int, Rational>();
        foreach (var term in Product(ProductKind.Geometric, rest, b))
            MultiplyByVector(sum, i, term.Blade, term.Coefficient);
        foreach (var c in LeftContractVector(i, rest))
            Accumulate(sum, Product(ProductKind.Geometric, c.Blade, b), -c.Coefficient);
        return ToTerms(sum);
    }

    /// <summary>Adds factor · e_i e_X = factor · (e_i ⌋ e_X + e_i ∧ e_X) into sum.</summary>
    private void MultiplyByVector(Dictionary<int, Rational> sum, int i, int x, Rational factor)
    {
        foreach (var c in LeftContractVector(i, x)) Add(sum, c.Blade, factor * c.Coefficient);
        if ((x & (1 << i)) == 0) Add(sum, x | (1 << i), factor * BasisBlade.OuterSign(1 << i, x));
    }

    /// <summary>e_i ⌋ (e_x1 ∧ … ∧ e_xk) = Σ_m (−1)^(m−1) B(e_i, e_xm) e_(X without xm).</summary>
    private IEnumerable<BladeTerm> LeftContractVector(int i, int x)
    {
        var m = 0;
        for (var bits = x; bits != 0; bits &= bits - 1, m++)
        {
            var j = BitOperations.TrailingZeroCount(bits);
            var g = _metric[i, j];
            if (g.IsZero) continue;
            yield return new BladeTerm(x & ~(1 << j), (m & 1) == 0 ? g : -g);
        }
    }

    private static void Accumulate(Dictionary<int, Rational> sum, IEnumerable<BladeTerm> terms, Rational factor)
    {
        foreach (var t in terms) Add(sum, t.Blade, factor * t.Coefficient);
    }

    private static void Add(Dictionary<int, Rational> sum, int blade, Rational value)
    {
        if (value.IsZero) return;
        sum[blade] = sum.TryGetValue(blade, out var old) ? old + value : value;
    }

    private static BladeTerm[] ToTerms(Dictionary<int, Rational> sum) =>
        sum.Where(kv => !kv.Value.IsZero).OrderBy(kv => kv.Key).Select(kv => new BladeTerm(kv.Key, kv.Value)).ToArray();
}
