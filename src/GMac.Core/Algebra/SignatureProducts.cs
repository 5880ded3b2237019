using System.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// Blade products of a frame whose basis vectors are orthogonal and square to +1, −1 or 0
/// (Euclidean, signature and projective frames). Each product of two blades is at most one
/// signed blade, found with a few bit operations, so nothing is tabulated: a table would hold
/// up to 4^n entries and building it is what makes large frames slow.
/// </summary>
internal sealed class SignatureProducts
{
    /// <summary>Frames up to this many blades (8 dimensions) get a sign table per product kind: 64 KiB each at most.</summary>
    public const int TabulatedBladeCount = 256;

    private readonly int _negative; // basis vectors squaring to −1
    private readonly int _null;     // basis vectors squaring to 0
    private readonly int _bladeCount;
    private readonly sbyte[]?[] _signTables = new sbyte[]?[Enum.GetValues<ProductKind>().Length];

    private SignatureProducts(int negative, int nullVectors, int bladeCount)
    {
        _negative = negative;
        _null = nullVectors;
        _bladeCount = bladeCount;
    }

    /// <summary>
    /// The sign of every blade product of one kind, indexed by a · bladeCount + b (the blade is
    /// a XOR b), built on first use; null for frames above <see cref="TabulatedBladeCount"/> blades.
    /// </summary>
    public sbyte[]? SignTable(ProductKind kind)
    {
        if (_bladeCount > TabulatedBladeCount) return null;
        var table = _signTables[(int)kind];
        if (table is not null) return table;
        table = new sbyte[_bladeCount * _bladeCount];
        for (var a = 0; a < _bladeCount; a++)
        for (var b = 0; b < _bladeCount; b++)
            table[a * _bladeCount + b] = (sbyte)Product(kind, a, b, out _);
        return _signTables[(int)kind] = table; // a benign race: every builder fills the same table
    }

    /// <summary>The products of a metric, or null when it is not diagonal with entries in {−1, 0, 1}.</summary>
    public static SignatureProducts? For(Metric metric)
    {
        if (!metric.IsDiagonal) return null;
        int negative = 0, nullVectors = 0;
        for (var i = 0; i < metric.Dimension; i++)
        {
            var square = metric[i, i];
            if (square.IsZero) nullVectors |= 1 << i;
            else if (square == Numerics.Rational.MinusOne) negative |= 1 << i;
            else if (!square.IsOne) return null;
        }
        return new SignatureProducts(negative, nullVectors, 1 << metric.Dimension);
    }

    /// <summary>
    /// The product of blades a and b of the given kind: sign · e_blade, or sign 0 when it vanishes.
    /// </summary>
    public int Product(ProductKind kind, int a, int b, out int blade)
    {
        blade = a ^ b;
        var common = a & b;
        if ((common & _null) != 0) return 0;
        var ga = BitOperations.PopCount((uint)a);
        var gb = BitOperations.PopCount((uint)b);
        var g = BitOperations.PopCount((uint)blade);
        var keep = kind switch
        {
            ProductKind.Geometric or ProductKind.Commutator or ProductKind.AntiCommutator => true,
            ProductKind.Outer => common == 0,
            ProductKind.LeftContraction => g == gb - ga,
            ProductKind.RightContraction => g == ga - gb,
            ProductKind.Scalar => g == 0,
            ProductKind.FatDot => g == Math.Abs(gb - ga),
            ProductKind.HestenesInner => ga != 0 && gb != 0 && g == Math.Abs(gb - ga),
            _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown product."),
        };
        if (!keep) return 0;
        var sign = BasisBlade.OuterSign(a, b);
        if ((BitOperations.PopCount((uint)(common & _negative)) & 1) != 0) sign = -sign;
        if (kind is ProductKind.Commutator or ProductKind.AntiCommutator)
        {
            // ½(ab ∓ ba): ba differs from ab only by the reordering sign, so the half sum is ab or 0.
            var commute = BasisBlade.OuterSign(b, a) == BasisBlade.OuterSign(a, b);
            if (commute == (kind == ProductKind.Commutator)) return 0;
        }
        return sign;
    }
}
