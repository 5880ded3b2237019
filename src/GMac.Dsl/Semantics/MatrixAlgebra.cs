using GMac.Core.Numerics;

namespace GMac.Dsl.Semantics;

/// <summary>Exact operations on small rational matrices used to resolve frames and transforms.</summary>
internal static class MatrixAlgebra
{
    public static Rational[,] Identity(int n)
    {
        var m = new Rational[n, n];
        for (var i = 0; i < n; i++) m[i, i] = Rational.One;
        return m;
    }

    public static Rational[,] Diagonal(IReadOnlyList<Rational> values)
    {
        var m = new Rational[values.Count, values.Count];
        for (var i = 0; i < values.Count; i++) m[i, i] = values[i];
        return m;
    }

    public static Rational[,] Transpose(Rational[,] a)
    {
        var t = new Rational[a.GetLength(1), a.GetLength(0)];
        for (var i = 0; i < a.GetLength(0); i++)
        for (var j = 0; j < a.GetLength(1); j++)
            t[j, i] = a[i, j];
        return t;
    }

    public static Rational[,] Multiply(Rational[,] a, Rational[,] b)
    {
        var n = a.GetLength(0);
        var k = a.GetLength(1);
        var m = b.GetLength(1);
        var c = new Rational[n, m];
        for (var i = 0; i < n; i++)
        for (var j = 0; j < m; j++)
        {
            var s = Rational.Zero;
            for (var l = 0; l < k; l++) s += a[i, l] * b[l, j];
            c[i, j] = s;
        }
        return c;
    }

    public static bool IsSymmetric(Rational[,] a, out int row, out int column)
    {
        for (row = 0; row < a.GetLength(0); row++)
        for (column = row + 1; column < a.GetLength(1); column++)
            if (a[row, column] != a[column, row]) return false;
        row = column = -1;
        return true;
    }

    /// <summary>Gauss-Jordan inverse; null when the matrix is singular.</summary>
    public static Rational[,]? Inverse(Rational[,] a)
    {
        var n = a.GetLength(0);
        if (n != a.GetLength(1)) return null;
        var m = (Rational[,])a.Clone();
        var inv = Identity(n);
        for (var col = 0; col < n; col++)
        {
            var pivot = -1;
            for (var r = col; r < n; r++)
                if (!m[r, col].IsZero) { pivot = r; break; }
            if (pivot < 0) return null;
            SwapRows(m, pivot, col);
            SwapRows(inv, pivot, col);
            var p = m[col, col];
            for (var j = 0; j < n; j++)
            {
                m[col, j] /= p;
                inv[col, j] /= p;
            }
            for (var r = 0; r < n; r++)
            {
                if (r == col || m[r, col].IsZero) continue;
                var f = m[r, col];
                for (var j = 0; j < n; j++)
                {
                    m[r, j] -= f * m[col, j];
                    inv[r, j] -= f * inv[col, j];
                }
            }
        }
        return inv;
    }

    private static void SwapRows(Rational[,] m, int a, int b)
    {
        if (a == b) return;
        for (var j = 0; j < m.GetLength(1); j++) (m[a, j], m[b, j]) = (m[b, j], m[a, j]);
    }

    /// <summary>
    /// An orthogonal basis for the symmetric bilinear form <paramref name="ipm"/> by
    /// congruence (rational Gram-Schmidt with a fix for null pivots), each vector
    /// scaled to square ±1 when that needs no irrational factor. For the conformal
    /// basis (no, ni with no·ni = −1) this yields e = no − ni/2 and ē = no + ni/2.
    /// Returns the basis change matrix (row i = new vector i in old coordinates) and
    /// the new diagonal IPM.
    /// </summary>
    public static (Rational[,] Bcm, Rational[,] Ipm) Orthogonalize(Rational[,] ipm)
    {
        var n = ipm.GetLength(0);
        var vectors = new List<Rational[]>();
        for (var i = 0; i < n; i++)
        {
            var v = new Rational[n];
            v[i] = Rational.One;
            vectors.Add(v);
        }

        Rational Dot(Rational[] x, Rational[] y)
        {
            var s = Rational.Zero;
            for (var i = 0; i < n; i++)
            {
                if (x[i].IsZero) continue;
                for (var j = 0; j < n; j++)
                    if (!y[j].IsZero) s += x[i] * ipm[i, j] * y[j];
            }
            return s;
        }

        for (var k = 0; k < n; k++)
        {
            // Prefer a remaining vector with a non-zero square; else mix a null pair.
            var pick = -1;
            for (var i = k; i < n; i++)
                if (!Dot(vectors[i], vectors[i]).IsZero) { pick = i; break; }
            if (pick < 0)
            {
                for (var i = k; i < n && pick < 0; i++)
                for (var j = i + 1; j < n; j++)
                {
                    var p = Dot(vectors[i], vectors[j]);
                    if (p.IsZero) continue;
                    // (vi + c vj)² = 2 c p when both are null; c = 1/(2p) gives +1.
                    var c = Rational.One / (2 * p);
                    for (var t = 0; t < n; t++) vectors[i][t] += c * vectors[j][t];
                    pick = i;
                    break;
                }
            }
            if (pick < 0) break; // the rest is a null, mutually orthogonal block
            (vectors[k], vectors[pick]) = (vectors[pick], vectors[k]);
            var vk = vectors[k];
            var sq = Dot(vk, vk);
            for (var i = k + 1; i < n; i++)
            {
                var f = Dot(vectors[i], vk) / sq;
                if (f.IsZero) continue;
                for (var t = 0; t < n; t++) vectors[i][t] -= f * vk[t];
            }
        }

        var bcm = new Rational[n, n];
        var diag = new Rational[n];
        for (var i = 0; i < n; i++)
        {
            var v = vectors[i];
            var sq = Dot(v, v);
            if (!sq.IsZero && sq.Abs().Reciprocal().TryExactSqrt(out var scale))
            {
                for (var t = 0; t < n; t++) v[t] *= scale;
                sq = sq.Sign > 0 ? Rational.One : Rational.MinusOne;
            }
            diag[i] = sq;
            for (var t = 0; t < n; t++) bcm[i, t] = v[t];
        }
        return (bcm, Diagonal(diag));
    }
}
