using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class PolynomialDivision_Exactness
{
    private static readonly Scalar[] Atoms =
    [
        Scalar.Variable("a"), Scalar.Variable("b"), Scalar.Variable("c"),
        Scalar.Sqrt(Scalar.Variable("a") + Scalar.Variable("b")), Scalar.Sin(Scalar.Variable("c")),
    ];

    private static Scalar RandomPolynomial(Random random, int terms, int degree)
    {
        var sum = Scalar.Zero;
        for (var t = 0; t < terms; t++)
        {
            Scalar term = random.Next(-5, 6) is var k && k == 0 ? 1 : k;
            for (var d = random.Next(degree + 1); d > 0; d--)
                term *= Atoms[random.Next(Atoms.Length)];
            sum += term;
        }
        return sum;
    }

    [Fact]
    public void A_product_divides_back_into_its_other_factor()
    {
        var random = new Random(7);
        for (var trial = 0; trial < 60; trial++)
        {
            var s = RandomPolynomial(random, 1 + random.Next(5), 3);
            var q = RandomPolynomial(random, 1 + random.Next(12), 3);
            if (Scalar.IsZero(s) || Scalar.IsZero(q)) continue;
            Assert.True(InverseCancellation.TryDivide(q * s, s, out var quotient), $"{q} · {s}");
            Assert.Same(q, quotient);
        }
    }

    [Fact]
    public void A_remainder_the_divisor_cannot_absorb_is_refused()
    {
        var random = new Random(8);
        for (var trial = 0; trial < 40; trial++)
        {
            var s = RandomPolynomial(random, 2 + random.Next(4), 3);
            var q = RandomPolynomial(random, 1 + random.Next(8), 2);
            if (s.IsConstant || Scalar.IsZero(q)) continue;
            // A constant is divisible by no non-constant s.
            Assert.False(InverseCancellation.TryDivide(q * s + 1, s, out _), $"{q} · {s} + 1");
        }
    }

    [Fact]
    public void Cancelling_a_sum_against_its_inverse_leaves_the_quotient()
    {
        var random = new Random(9);
        for (var trial = 0; trial < 30; trial++)
        {
            var s = RandomPolynomial(random, 2 + random.Next(3), 2);
            var q = RandomPolynomial(random, 1 + random.Next(6), 2);
            var rest = RandomPolynomial(random, 2, 1);
            if (s.IsConstant || Scalar.IsZero(q)) continue;
            // q·s / s + rest, with 1/s an atom of the expression.
            var e = q * s * Scalar.Reciprocal(s) + rest;
            Assert.Same(q + rest, InverseCancellation.Cancel(e));
        }
    }
}
