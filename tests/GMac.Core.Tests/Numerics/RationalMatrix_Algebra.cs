using GMac.Core.Numerics;

namespace GMac.Core.Tests.Numerics;

public class RationalMatrix_Algebra
{
    private static RationalMatrix RandomMatrix(Random random, int rows, int columns)
    {
        var entries = new Rational[rows, columns];
        for (var i = 0; i < rows; i++)
        for (var j = 0; j < columns; j++)
            entries[i, j] = new Rational(random.Next(-9, 10), random.Next(1, 5));
        return new RationalMatrix(entries);
    }

    /// <summary>The Leibniz formula: an independent, if slow, definition of the determinant.</summary>
    private static Rational LeibnizDeterminant(RationalMatrix m)
    {
        var n = m.Rows;
        var total = Rational.Zero;
        foreach (var permutation in Permutations(Enumerable.Range(0, n).ToArray(), 0))
        {
            var inversions = 0;
            for (var i = 0; i < n; i++)
            for (var j = i + 1; j < n; j++)
                if (permutation[i] > permutation[j]) inversions++;
            var term = inversions % 2 == 0 ? Rational.One : Rational.MinusOne;
            for (var i = 0; i < n; i++) term *= m[i, permutation[i]];
            total += term;
        }
        return total;
    }

    private static IEnumerable<int[]> Permutations(int[] items, int from)
    {
        if (from == items.Length)
        {
            yield return (int[])items.Clone();
            yield break;
        }
        for (var i = from; i < items.Length; i++)
        {
            (items[from], items[i]) = (items[i], items[from]);
            foreach (var p in Permutations(items, from + 1)) yield return p;
            (items[from], items[i]) = (items[i], items[from]);
        }
    }

    [Fact]
    public void Determinant_equals_the_leibniz_formula()
    {
        var random = new Random(7);
        for (var n = 1; n <= 5; n++)
            for (var trial = 0; trial < 10; trial++)
            {
                var m = RandomMatrix(random, n, n);
                Assert.Equal(LeibnizDeterminant(m), m.Determinant());
            }
    }

    [Fact]
    public void Inverse_times_matrix_is_the_identity_on_both_sides()
    {
        var random = new Random(11);
        for (var n = 1; n <= 6; n++)
        {
            var m = RandomMatrix(random, n, n);
            if (m.Determinant().IsZero) continue;
            var inverse = m.Inverse();
            Assert.Equal(RationalMatrix.Identity(n), m * inverse);
            Assert.Equal(RationalMatrix.Identity(n), inverse * m);
            Assert.Equal(m.Determinant().Reciprocal(), inverse.Determinant());
        }
    }

    [Fact]
    public void Determinant_is_multiplicative_and_transpose_invariant()
    {
        var random = new Random(13);
        for (var trial = 0; trial < 10; trial++)
        {
            var a = RandomMatrix(random, 4, 4);
            var b = RandomMatrix(random, 4, 4);
            Assert.Equal(a.Determinant() * b.Determinant(), (a * b).Determinant());
            Assert.Equal(a.Determinant(), a.Transpose().Determinant());
        }
    }

    [Fact]
    public void Singular_matrices_have_no_inverse()
    {
        var m = RationalMatrix.FromRows([[1, 2, 3], [2, 4, 6], [0, 1, 1]]);
        Assert.True(m.Determinant().IsZero);
        Assert.False(m.TryInverse(out _));
        Assert.Throws<InvalidOperationException>(() => m.Inverse());
    }

    [Fact]
    public void Pivoting_handles_a_zero_leading_entry()
    {
        var m = RationalMatrix.FromRows([[0, 1], [1, 0]]);
        Assert.Equal(Rational.MinusOne, m.Determinant());
        Assert.Equal(m, m.Inverse());
    }

    [Fact]
    public void Product_of_non_conforming_shapes_and_non_square_determinant_are_refused()
    {
        var a = RandomMatrix(new Random(3), 2, 3);
        Assert.Throws<ArgumentException>(() => a * a);
        Assert.Throws<ArgumentException>(() => RationalMatrix.FromRows([[1, 2], [3]]));
        Assert.Throws<InvalidOperationException>(() => a.Determinant());
        Assert.Equal(RandomMatrix(new Random(3), 2, 3), a);
        Assert.False(a.IsSquare);
        Assert.Equal(3, a.Transpose().Rows);
    }

    [Fact]
    public void Symmetry_and_diagonal_shape_are_detected()
    {
        Assert.True(RationalMatrix.FromRows([[1, 2], [2, 5]]).IsSymmetric);
        Assert.False(RationalMatrix.FromRows([[1, 2], [3, 5]]).IsSymmetric);
        Assert.True(RationalMatrix.Diagonal([1, -1, 0]).IsDiagonal);
        Assert.False(RationalMatrix.FromRows([[1, 2], [2, 5]]).IsDiagonal);
    }
}
