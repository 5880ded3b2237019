using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// The symmetric bilinear form of a frame, given by its inner-product matrix (IPM) over exact
/// rationals. It may be non-diagonal (the conformal null basis) or degenerate (projective GA).
/// </summary>
public sealed class Metric
{
    public RationalMatrix Matrix { get; }
    public int Dimension => Matrix.Rows;
    public bool IsDiagonal { get; }

    private Metric(RationalMatrix matrix)
    {
        Matrix = matrix;
        IsDiagonal = matrix.IsDiagonal;
    }

    public Rational this[int i, int j] => Matrix[i, j];

    /// <summary>p basis vectors squaring to +1, then q to −1, then r to 0.</summary>
    public static Metric FromSignature(int p, int q, int r = 0, string? frameName = null)
    {
        if (p < 0 || q < 0 || r < 0)
            throw new AlgebraException(frameName, $"a signature needs non-negative counts, not ({p}, {q}, {r}).");
        var diagonal = new List<Rational>();
        for (var i = 0; i < p; i++) diagonal.Add(Rational.One);
        for (var i = 0; i < q; i++) diagonal.Add(Rational.MinusOne);
        for (var i = 0; i < r; i++) diagonal.Add(Rational.Zero);
        return FromDiagonal(diagonal, frameName);
    }

    public static Metric Euclidean(int n, string? frameName = null) => FromSignature(n, 0, 0, frameName);

    public static Metric FromDiagonal(IReadOnlyList<Rational> diagonal, string? frameName = null)
    {
        CheckDimension(diagonal.Count, frameName);
        return new Metric(RationalMatrix.Diagonal(diagonal));
    }

    /// <summary>Any symmetric inner-product matrix.</summary>
    public static Metric FromMatrix(RationalMatrix matrix, string? frameName = null)
    {
        if (!matrix.IsSquare)
            throw new AlgebraException(frameName, $"the inner-product matrix must be square, but it is {matrix.Rows}x{matrix.Columns}.");
        CheckDimension(matrix.Rows, frameName);
        for (var i = 0; i < matrix.Rows; i++)
        for (var j = i + 1; j < matrix.Columns; j++)
            if (matrix[i, j] != matrix[j, i])
                throw new AlgebraException(frameName,
                    $"the inner-product matrix must be symmetric, but entry ({i + 1},{j + 1}) is {matrix[i, j]} and entry ({j + 1},{i + 1}) is {matrix[j, i]}.");
        return new Metric(matrix);
    }

    public static Metric FromMatrix(Rational[,] matrix, string? frameName = null) => FromMatrix(new RationalMatrix(matrix), frameName);

    private static void CheckDimension(int n, string? frameName)
    {
        if (n < 1)
            throw new AlgebraException(frameName, "a frame needs at least one basis vector.");
        if (n > Frame.MaxDimension)
            throw new AlgebraException(frameName, $"{n} basis vectors are too many; at most {Frame.MaxDimension} are supported.");
    }

    /// <summary>True when no non-zero vector is orthogonal to every vector.</summary>
    public bool IsDegenerate => Matrix.Determinant().IsZero;

    /// <summary>True when every non-zero vector has a positive square (Euclidean metrics).</summary>
    public bool IsPositiveDefinite
    {
        get
        {
            // Sylvester's criterion: every leading principal minor is positive.
            for (var k = 1; k <= Dimension; k++)
            {
                var minor = new Rational[k, k];
                for (var i = 0; i < k; i++)
                for (var j = 0; j < k; j++)
                    minor[i, j] = Matrix[i, j];
                if (new RationalMatrix(minor).Determinant().Sign <= 0) return false;
            }
            return true;
        }
    }
}
