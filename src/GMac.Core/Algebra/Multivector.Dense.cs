using System.Numerics;

namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    /// <summary>
    /// Frames up to this many blades (8 dimensions) store value-type coefficients densely: 2 KiB of
    /// doubles at most, and the sign tables of orthogonal frames exist up to the same size.
    /// </summary>
    public const int DenseBladeLimit = SignatureProducts.TabulatedBladeCount;

    // Symbolic coefficients are objects whose zeros still cost a product; they stay sparse.
    private static readonly bool ValueCoefficients = typeof(T).IsValueType;

    /// <summary>Whether multivectors of this scalar type in this frame use the dense form.</summary>
    public static bool IsDenseFrame(Frame frame) => ValueCoefficients && frame.BladeCount <= DenseBladeLimit;

    /// <summary>The non-zero coefficients of a dense array from blade id <paramref name="from"/> on.</summary>
    private static int DenseTermCount(T[] dense, int from = 0)
    {
        var count = 0;
        for (var id = from; id < dense.Length; id++)
            if (!T.IsZero(dense[id])) count++;
        return count;
    }

    /// <summary>The blade ids of the non-zero terms, ascending, in either form.</summary>
    private IEnumerable<int> Ids()
    {
        if (_dense is null) return _ids;
        return Enumerable.Range(0, _dense.Length).Where(id => !T.IsZero(_dense[id]));
    }

    /// <summary>f applied to the non-zero coefficients; zeros stay zero, as in the sparse form.</summary>
    private Multivector<T> DenseMap(Func<T, T> f)
    {
        var source = _dense!;
        var result = new T[source.Length];
        for (var id = 0; id < source.Length; id++)
            if (!T.IsZero(source[id])) result[id] = f(source[id]);
        return new Multivector<T>(Frame, result);
    }

    private static Multivector<T> DenseCombine(Multivector<T> a, T[] b, bool subtract)
    {
        var x = a._dense!;
        var result = new T[x.Length];
        if (subtract)
            for (var id = 0; id < x.Length; id++) result[id] = x[id] - b[id];
        else
            for (var id = 0; id < x.Length; id++) result[id] = x[id] + b[id];
        return new Multivector<T>(a.Frame, result);
    }

    /// <summary>Keeps the grades whose bit is set in <paramref name="keptGrades"/>, negating those set in <paramref name="negatedGrades"/>.</summary>
    private Multivector<T> DenseByGrade(int keptGrades, int negatedGrades)
    {
        var source = _dense!;
        var result = new T[source.Length];
        for (var id = 0; id < source.Length; id++)
        {
            var grade = 1 << BitOperations.PopCount((uint)id);
            if ((keptGrades & grade) == 0) continue;
            result[id] = (negatedGrades & grade) == 0 ? source[id] : -source[id];
        }
        return new Multivector<T>(Frame, result);
    }

    private static bool DenseEquals(T[] a, T[] b)
    {
        for (var id = 0; id < a.Length; id++)
            if (!a[id].Equals(b[id])) return false;
        return true;
    }

    /// <summary>
    /// A product of two dense multivectors: every pair of non-zero coefficients, in the order of
    /// the sparse form (a's blades ascending, then b's), so both forms give the same rounding.
    /// </summary>
    private Multivector<T> DenseProduct(ProductKind kind, T[] b)
    {
        var a = _dense!;
        var n = a.Length;
        var result = new T[n];
        if (Frame.SignatureProducts is { } signature)
        {
            // Dense frames have at most TabulatedBladeCount blades, so the table always exists.
            var signs = signature.SignTable(kind)!;
            if (kind == ProductKind.Scalar) DenseScalarProduct(signs, a, b, result);
            else DenseProduct(signs, a, b, result);
        }
        else
        {
            var table = ProductTable<T>.For(Frame, kind);
            if (table.Completed() is { } flat) DenseProduct(flat, a, b, result);
            else DenseProduct(table, a, b, result);
        }
        return new Multivector<T>(Frame, result);
    }

    /// <summary>An orthogonal frame: one signed blade a XOR b per pair of blades.</summary>
    private static void DenseProduct(sbyte[] signs, T[] a, T[] b, T[] result)
    {
        var n = a.Length;
        for (var i = 0; i < n; i++)
        {
            var ca = a[i];
            if (T.IsZero(ca)) continue;
            var row = i * n;
            for (var j = 0; j < n; j++)
            {
                var sign = signs[row + j];
                if (sign == 0) continue;
                var cb = b[j];
                if (T.IsZero(cb)) continue;
                var ab = ca * cb;
                result[i ^ j] += sign > 0 ? ab : -ab;
            }
        }
    }

    /// <summary>⟨AB⟩₀ in an orthogonal frame: only equal blades meet.</summary>
    private static void DenseScalarProduct(sbyte[] signs, T[] a, T[] b, T[] result)
    {
        var n = a.Length;
        var sum = T.Zero;
        for (var i = 0; i < n; i++)
        {
            var sign = signs[i * n + i];
            if (sign == 0 || T.IsZero(a[i]) || T.IsZero(b[i])) continue;
            var ab = a[i] * b[i];
            sum = sign > 0 ? sum + ab : sum - ab;
        }
        result[0] = sum;
    }

    /// <summary>A non-orthogonal frame of at most 64 blades: the terms of each pair from the flat table.</summary>
    private static void DenseProduct(ProductTable<T>.Flat flat, T[] a, T[] b, T[] result)
    {
        var (start, blades, coefficients) = (flat.Start, flat.Blades, flat.Coefficients);
        var n = a.Length;
        for (var i = 0; i < n; i++)
        {
            var ca = a[i];
            if (T.IsZero(ca)) continue;
            var row = i * n;
            for (var j = 0; j < n; j++)
            {
                var (first, end) = (start[row + j], start[row + j + 1]);
                if (first == end) continue;
                var cb = b[j];
                if (T.IsZero(cb)) continue;
                var ab = ca * cb;
                for (var k = first; k < end; k++) result[blades[k]] += coefficients[k] * ab;
            }
        }
    }

    /// <summary>A larger non-orthogonal frame: entries built on first use.</summary>
    private static void DenseProduct(ProductTable<T> table, T[] a, T[] b, T[] result)
    {
        var n = a.Length;
        for (var i = 0; i < n; i++)
        {
            var ca = a[i];
            if (T.IsZero(ca)) continue;
            for (var j = 0; j < n; j++)
            {
                var cb = b[j];
                if (T.IsZero(cb)) continue;
                var entry = table.Get(i, j);
                var blades = entry.Blades;
                if (blades.Length == 0) continue;
                var ab = ca * cb;
                for (var k = 0; k < blades.Length; k++)
                    result[blades[k]] += entry.IsOne[k] ? ab : entry.Coefficients[k] * ab;
            }
        }
    }
}
