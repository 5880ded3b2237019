using System.Text;

namespace GMac.Core.Numerics;

/// <summary>An immutable matrix of exact rationals (metrics, basis-change matrices).</summary>
public sealed class RationalMatrix : IEquatable<RationalMatrix>
{
    private readonly Rational[,] _entries;

    public int Rows { get; }
    public int Columns { get; }

    public RationalMatrix(Rational[,] entries)
    {
        Rows = entries.GetLength(0);
        Columns = entries.GetLength(1);
        _entries = (Rational[,])entries.Clone();
    }

    public static RationalMatrix FromRows(IReadOnlyList<IReadOnlyList<Rational>> rows)
    {
        var r = rows.Count;
        var c = r == 0 ? 0 : rows[0].Count;
        var entries = new Rational[r, c];
        for (var i = 0; i < r; i++)
        {
            if (rows[i].Count != c)
                throw new ArgumentException($"Row {i + 1} has {rows[i].Count} entries but row 1 has {c}: a matrix needs rows of equal length.");
            for (var j = 0; j < c; j++) entries[i, j] = rows[i][j];
        }
        return new RationalMatrix(entries);
    }

    public static RationalMatrix Identity(int n)
    {
        var e = new Rational[n, n];
        for (var i = 0; i < n; i++)
        for (var j = 0; j < n; j++)
            e[i, j] = i == j ? Rational.One : Rational.Zero;
        return new RationalMatrix(e);
    }

    public static RationalMatrix Diagonal(IReadOnlyList<Rational> diagonal)
    {
        var n = diagonal.Count;
        var e = new Rational[n, n];
        for (var i = 0; i < n; i++)
        for (var j = 0; j < n; j++)
            e[i, j] = i == j ? diagonal[i] : Rational.Zero;
        return new RationalMatrix(e);
    }

    public Rational this[int row, int column] => _entries[row, column];

    public bool IsSquare => Rows == Columns;

    public bool IsSymmetric => IsSquare && FirstAsymmetry() is null;

    /// <summary>The first entry (row &lt; column, 0-based) that differs from its mirror, or null for a symmetric matrix.</summary>
    public (int Row, int Column)? FirstAsymmetry()
    {
        RequireSquare("symmetry test");
        for (var i = 0; i < Rows; i++)
        for (var j = i + 1; j < Columns; j++)
            if (_entries[i, j] != _entries[j, i]) return (i, j);
        return null;
    }

    public bool IsDiagonal
    {
        get
        {
            if (!IsSquare) return false;
            for (var i = 0; i < Rows; i++)
            for (var j = 0; j < Columns; j++)
                if (i != j && !_entries[i, j].IsZero) return false;
            return true;
        }
    }

    public Rational[,] ToArray() => (Rational[,])_entries.Clone();

    public RationalMatrix Transpose()
    {
        var t = new Rational[Columns, Rows];
        for (var i = 0; i < Rows; i++)
        for (var j = 0; j < Columns; j++)
            t[j, i] = _entries[i, j];
        return new RationalMatrix(t);
    }

    public static RationalMatrix operator *(RationalMatrix a, RationalMatrix b)
    {
        if (a.Columns != b.Rows)
            throw new ArgumentException($"Cannot multiply a {a.Rows}x{a.Columns} matrix by a {b.Rows}x{b.Columns} matrix.");
        var p = new Rational[a.Rows, b.Columns];
        for (var i = 0; i < a.Rows; i++)
        for (var j = 0; j < b.Columns; j++)
        {
            var sum = Rational.Zero;
            for (var k = 0; k < a.Columns; k++)
            {
                var x = a._entries[i, k];
                if (!x.IsZero) sum += x * b._entries[k, j];
            }
            p[i, j] = sum;
        }
        return new RationalMatrix(p);
    }

    public Rational Determinant()
    {
        RequireSquare("determinant");
        var m = ToArray();
        var n = Rows;
        var det = Rational.One;
        for (var col = 0; col < n; col++)
        {
            var pivot = -1;
            for (var r = col; r < n; r++)
                if (!m[r, col].IsZero) { pivot = r; break; }
            if (pivot < 0) return Rational.Zero;
            if (pivot != col) { SwapRows(m, pivot, col); det = -det; }
            det *= m[col, col];
            for (var r = col + 1; r < n; r++)
            {
                if (m[r, col].IsZero) continue;
                var f = m[r, col] / m[col, col];
                for (var c = col; c < n; c++) m[r, c] -= f * m[col, c];
            }
        }
        return det;
    }

    /// <summary>The inverse; returns false for a singular matrix.</summary>
    public bool TryInverse(out RationalMatrix inverse)
    {
        RequireSquare("inverse");
        var n = Rows;
        var m = ToArray();
        var inv = Identity(n).ToArray();
        inverse = this;
        for (var col = 0; col < n; col++)
        {
            var pivot = -1;
            for (var r = col; r < n; r++)
                if (!m[r, col].IsZero) { pivot = r; break; }
            if (pivot < 0) return false;
            SwapRows(m, pivot, col);
            SwapRows(inv, pivot, col);
            var p = m[col, col];
            for (var c = 0; c < n; c++) { m[col, c] /= p; inv[col, c] /= p; }
            for (var r = 0; r < n; r++)
            {
                if (r == col || m[r, col].IsZero) continue;
                var f = m[r, col];
                for (var c = 0; c < n; c++) { m[r, c] -= f * m[col, c]; inv[r, c] -= f * inv[col, c]; }
            }
        }
        inverse = new RationalMatrix(inv);
        return true;
    }

    public RationalMatrix Inverse() =>
        TryInverse(out var inv) ? inv : throw new InvalidOperationException("The matrix is singular (its determinant is zero) and has no inverse.");

    private void RequireSquare(string what)
    {
        if (!IsSquare) throw new InvalidOperationException($"The {what} needs a square matrix, not {Rows}x{Columns}.");
    }

    private static void SwapRows(Rational[,] m, int a, int b)
    {
        if (a == b) return;
        for (var c = 0; c < m.GetLength(1); c++) (m[a, c], m[b, c]) = (m[b, c], m[a, c]);
    }

    public bool Equals(RationalMatrix? other)
    {
        if (other is null || other.Rows != Rows || other.Columns != Columns) return false;
        for (var i = 0; i < Rows; i++)
        for (var j = 0; j < Columns; j++)
            if (_entries[i, j] != other._entries[i, j]) return false;
        return true;
    }

    public override bool Equals(object? obj) => Equals(obj as RationalMatrix);

    public override int GetHashCode()
    {
        var h = new HashCode();
        foreach (var e in _entries) h.Add(e);
        return h.ToHashCode();
    }

    public override string ToString()
    {
        var sb = new StringBuilder("{");
        for (var i = 0; i < Rows; i++)
        {
            if (i > 0) sb.Append(", ");
            sb.Append('{');
            for (var j = 0; j < Columns; j++)
            {
                if (j > 0) sb.Append(", ");
                sb.Append(_entries[i, j].ToString());
            }
            sb.Append('}');
        }
        return sb.Append('}').ToString();
    }
}
