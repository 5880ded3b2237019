using System.Numerics;
using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// The general inverse of random multivectors with small integer coefficients, exact, against the
/// solution x of A x = 1 found by inverting the 2ⁿ×2ⁿ matrix of left multiplication by A in rationals.
/// That matrix is built here from its own basis-blade product (swap count and squares of shared
/// vectors of a diagonal metric), not from the engine's tables; A is invertible exactly where it is.
/// </summary>
public class GeneralInverse_SolvesLeftMultiplication
{
    public static IEnumerable<object[]> Signatures() =>
    [
        [new[] { 1 }], [new[] { -1 }], [new[] { 1, 1 }], [new[] { 1, -1 }], [new[] { 1, 0 }],
        [new[] { 1, 1, 1 }], [new[] { 1, 1, -1 }], [new[] { 0, 1, 1 }],
        [new[] { 1, 1, 1, 1 }], [new[] { 1, -1, -1, -1 }], [new[] { 0, 1, 1, 1 }], [new[] { 1, 1, 1, -1 }],
        [new[] { 1, 1, 1, 1, 1 }], [new[] { 1, 1, 1, 1, -1 }], [new[] { 0, 1, 1, 1, 1 }], [new[] { 1, 1, -1, -1, -1 }],
    ];

    [Theory]
    [MemberData(nameof(Signatures))]
    public void Agrees_with_the_left_multiplication_matrix(int[] squares)
    {
        var frame = new Frame("f", squares.Select((_, i) => $"e{i + 1}").ToArray(),
            Metric.FromDiagonal(squares.Select(s => (Rational)s).ToArray()));
        var random = new Random(squares.Length * 31 + squares.Sum() + 7);
        var invertible = 0;
        for (var trial = 0; trial < 4; trial++)
        {
            var coefficients = Enumerable.Range(0, frame.BladeCount).Select(_ => random.Next(-3, 4)).ToArray();
            var a = Multivector<Scalar>.FromTerms(frame, coefficients.Select((c, id) => (new BasisBlade(id), (Scalar)c)));
            if (a.IsZero) continue;
            if (LeftMultiplication(squares, coefficients).TryInverse(out var inverse))
            {
                invertible++;
                var result = a.GeneralInverse();
                for (var id = 0; id < frame.BladeCount; id++)
                {
                    Assert.True(result[new BasisBlade(id)].TryGetConstant(out var c), $"blade {id} is not a constant");
                    Assert.Equal(inverse[id, 0], c);
                }
            }
            else
            {
                Assert.Throws<AlgebraException>(() => a.GeneralInverse());
            }
        }
        Assert.True(invertible > 0, "no trial drew an invertible multivector");
    }

    [Theory]
    [InlineData(new[] { 1, 1, 1 }, 0b001)]
    [InlineData(new[] { 0, 1, 1, 1 }, 0b0001)]
    [InlineData(new[] { 1, 1, 1, -1, 1 }, 0b01000)]
    public void One_plus_a_null_or_unit_vector_has_none(int[] squares, int vector)
    {
        // (1 + e)(1 − e) = 1 − e² is zero for e² = 1; 1 + e0 with e0² = 0 is invertible (1 − e0),
        // so only the unit vectors make the matrix singular.
        var frame = new Frame("f", squares.Select((_, i) => $"e{i + 1}").ToArray(),
            Metric.FromDiagonal(squares.Select(s => (Rational)s).ToArray()));
        var coefficients = new int[frame.BladeCount];
        coefficients[0] = 1;
        coefficients[vector] = 1;
        var a = Multivector<Scalar>.FromTerms(frame, coefficients.Select((c, id) => (new BasisBlade(id), (Scalar)c)));
        var singular = !LeftMultiplication(squares, coefficients).TryInverse(out _);
        Assert.Equal(squares[BitOperations.Log2((uint)vector)] == 1, singular);
        if (singular) Assert.Throws<AlgebraException>(() => a.GeneralInverse());
        else Assert.All((a.Gp(a.GeneralInverse()) - Multivector<Scalar>.FromScalar(frame, 1)).Terms, t => Assert.True(Scalar.IsZero(t.Coefficient)));
    }

    /// <summary>Column j holds the coefficients of A eⱼ.</summary>
    private static RationalMatrix LeftMultiplication(int[] squares, int[] a)
    {
        var size = 1 << squares.Length;
        var m = new Rational[size, size];
        for (var i = 0; i < size; i++)
            for (var j = 0; j < size; j++)
                m[i, j] = Rational.Zero;
        for (var i = 0; i < size; i++)
            for (var j = 0; j < size; j++)
                m[i ^ j, j] += a[i] * BladeProductSign(squares, i, j);
        return new RationalMatrix(m);
    }

    /// <summary>eᵢ eⱼ = sign e_(i xor j): one −1 per pair (bit of i above a bit of j), times the squares of shared vectors.</summary>
    private static int BladeProductSign(int[] squares, int i, int j)
    {
        var sign = 1;
        for (var bit = 0; bit < squares.Length; bit++)
        {
            if ((j & (1 << bit)) == 0) continue;
            if (BitOperations.PopCount((uint)(i >> (bit + 1))) % 2 == 1) sign = -sign;
            if ((i & (1 << bit)) != 0) sign *= squares[bit];
        }
        return sign;
    }
}
