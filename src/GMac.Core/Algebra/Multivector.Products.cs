using System.Numerics;

namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    /// <summary>
    /// Pairs of terms one product may multiply (two general multivectors of 11 dimensions). A
    /// product of two dense multivectors grows as 4^n; past this it would run for minutes and
    /// take gigabytes with symbolic coefficients, so it is refused with a message instead.
    /// </summary>
    public const long MaxProductPairs = 1L << 22;

    /// <summary>Any bilinear product of Table 3-2, term by term through the frame's product tables.</summary>
    public Multivector<T> Product(ProductKind kind, Multivector<T> other)
    {
        RequireSameFrame(this, other, "multiply");
        if (_dense is not null) return DenseProduct(kind, other._dense!);
        if (IsZero || other.IsZero) return Zero(Frame);
        if (Frame.SignatureProducts is { } signature && kind == ProductKind.Scalar) return ScalarProduct(signature, other);
        CheckSize(other);
        var acc = Accumulator.Rent(Frame);
        try
        {
            if (Frame.SignatureProducts is not { } signs)
            {
                var table = ProductTable<T>.For(Frame, kind);
                if (table.Flattened() is { } flat) AddProducts(flat, other, acc);
                else AddProducts(table, other, acc);
            }
            else if (signs.SignTable(kind) is { } table) AddProducts(table, other, acc);
            else AddProducts(signs, kind, other, acc);
            return acc.ToMultivector(Frame);
        }
        finally
        {
            acc.Return();
        }
    }

    /// <summary>A non-orthogonal frame: each pair of blades gives a list of blades with exact coefficients.</summary>
    private void AddProducts(ProductTable<T> table, Multivector<T> other, Accumulator acc)
    {
        var bIds = other._ids;
        var bCs = other._coefficients;
        for (var i = 0; i < _ids.Length; i++)
        {
            var a = _ids[i];
            var ca = _coefficients[i];
            for (var j = 0; j < bIds.Length; j++)
            {
                var entry = table.Get(a, bIds[j]);
                var blades = entry.Blades;
                if (blades.Length == 0) continue;
                var ab = ca * bCs[j];
                for (var k = 0; k < blades.Length; k++)
                    acc.Add(blades[k], entry.IsOne[k] ? ab : entry.Coefficients[k] * ab);
            }
        }
    }

    /// <summary>A small non-orthogonal frame: the terms of each pair of blades from the flat table.</summary>
    private void AddProducts(ProductTable<T>.Flat flat, Multivector<T> other, Accumulator acc)
    {
        var (start, blades, coefficients) = (flat.Start, flat.Blades, flat.Coefficients);
        var bIds = other._ids;
        var bCs = other._coefficients;
        var n = Frame.BladeCount;
        for (var i = 0; i < _ids.Length; i++)
        {
            var row = _ids[i] * n;
            var ca = _coefficients[i];
            for (var j = 0; j < bIds.Length; j++)
            {
                var p = row + bIds[j];
                var (first, end) = (start[p], start[p + 1]);
                if (first == end) continue;
                var ab = ca * bCs[j];
                for (var k = first; k < end; k++) acc.Add(blades[k], coefficients[k] * ab);
            }
        }
    }

    /// <summary>An orthogonal frame of at most 8 dimensions: one signed blade a XOR b per pair, its sign from a table.</summary>
    private void AddProducts(sbyte[] signTable, Multivector<T> other, Accumulator acc)
    {
        var bIds = other._ids;
        var bCs = other._coefficients;
        var n = Frame.BladeCount;
        for (var i = 0; i < _ids.Length; i++)
        {
            var a = _ids[i];
            var ca = _coefficients[i];
            var row = a * n;
            for (var j = 0; j < bIds.Length; j++)
            {
                var sign = signTable[row + bIds[j]];
                if (sign == 0) continue;
                var ab = ca * bCs[j];
                acc.Add(a ^ bIds[j], sign > 0 ? ab : -ab);
            }
        }
    }

    /// <summary>A larger orthogonal frame: the sign of each pair from a few bit operations.</summary>
    private void AddProducts(SignatureProducts signature, ProductKind kind, Multivector<T> other, Accumulator acc)
    {
        var bIds = other._ids;
        var bCs = other._coefficients;
        for (var i = 0; i < _ids.Length; i++)
        {
            var a = _ids[i];
            var ca = _coefficients[i];
            for (var j = 0; j < bIds.Length; j++)
            {
                var sign = signature.Product(kind, a, bIds[j], out var blade);
                if (sign == 0) continue;
                var ab = ca * bCs[j];
                acc.Add(blade, sign > 0 ? ab : -ab);
            }
        }
    }

    /// <summary>⟨AB⟩₀ in an orthonormal frame: only equal blades meet, so one merge of the sorted terms.</summary>
    private Multivector<T> ScalarProduct(SignatureProducts signature, Multivector<T> other)
    {
        var sum = T.Zero;
        var any = false;
        for (int i = 0, j = 0; i < _ids.Length && j < other._ids.Length;)
        {
            if (_ids[i] < other._ids[j]) { i++; continue; }
            if (_ids[i] > other._ids[j]) { j++; continue; }
            var sign = signature.Product(ProductKind.Scalar, _ids[i], _ids[i], out _);
            if (sign != 0)
            {
                var ab = _coefficients[i] * other._coefficients[j];
                sum = any ? (sign > 0 ? sum + ab : sum - ab) : (sign > 0 ? ab : -ab);
                any = true;
            }
            i++;
            j++;
        }
        return any ? FromScalar(Frame, sum) : Zero(Frame);
    }

    private void CheckSize(Multivector<T> other)
    {
        var pairs = (long)_ids.Length * other._ids.Length;
        if (pairs > MaxProductPairs)
            throw new AlgebraException(Frame.Name,
                $"a product of a multivector of {_ids.Length} terms and one of {other._ids.Length} terms in this {Frame.Dimension}-dimensional frame " +
                $"needs {pairs} term products, more than the limit of {MaxProductPairs}; restrict the operands to the grades needed (e.g. with grade(A, k) or a smaller class)")
            { ExceedsLimit = true };
    }

    public Multivector<T> Gp(Multivector<T> b) => Product(ProductKind.Geometric, b);
    public Multivector<T> Op(Multivector<T> b) => Product(ProductKind.Outer, b);
    public Multivector<T> Lcp(Multivector<T> b) => Product(ProductKind.LeftContraction, b);
    public Multivector<T> Rcp(Multivector<T> b) => Product(ProductKind.RightContraction, b);
    public Multivector<T> Fdp(Multivector<T> b) => Product(ProductKind.FatDot, b);
    public Multivector<T> Hip(Multivector<T> b) => Product(ProductKind.HestenesInner, b);
    public Multivector<T> Cp(Multivector<T> b) => Product(ProductKind.Commutator, b);
    public Multivector<T> Acp(Multivector<T> b) => Product(ProductKind.AntiCommutator, b);

    /// <summary>The scalar product A * B = ⟨AB⟩₀, as a scalar multivector.</summary>
    public Multivector<T> Sp(Multivector<T> b) => Product(ProductKind.Scalar, b);

    /// <summary>The scalar product as a plain scalar.</summary>
    public T ScalarProduct(Multivector<T> b) => Sp(b).ScalarPart;
}
