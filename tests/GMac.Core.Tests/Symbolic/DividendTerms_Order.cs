using GMac.Core.CodeGeneration.Rewrites;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class DividendTerms_Order
{
    private static readonly Scalar[] Atoms =
    [
        Scalar.Variable("a"), Scalar.Variable("b"), Scalar.Variable("c"),
        Scalar.Sqrt(Scalar.Variable("a") + Scalar.Variable("b")), Scalar.Reciprocal(Scalar.Variable("c") + Scalar.One),
    ];

    private static Scalar RandomPolynomial(Random random, int terms, int degree)
    {
        var sum = Scalar.Zero;
        for (var t = 0; t < terms; t++)
        {
            Scalar term = random.Next(-3, 4) is var k && k == 0 ? 1 : k;
            for (var d = random.Next(degree + 1); d > 0; d--) term *= Atoms[random.Next(Atoms.Length)];
            sum += term;
        }
        return sum;
    }

    [Fact]
    public void The_leading_term_after_each_subtraction_is_the_greatest_remaining_one()
    {
        var random = new Random(41);
        for (var trial = 0; trial < 60; trial++)
        {
            var b = RandomPolynomial(random, 3 + random.Next(10), 3);
            var s = RandomPolynomial(random, 2 + random.Next(3), 2);
            if (b.TermArray.Length == 0 || s.TermArray.Length < 2) continue;
            var dividend = new DividendTerms(b, DivisionTerms.CompareDescendingAtoms);
            var expected = b;
            var lead = s.TermArray[0];
            for (var step = 0; step < 12 && dividend.Count > 0; step++)
            {
                var top = dividend.Leading();
                var greatest = DivisionTerms.Leading(expected.Terms, DivisionTerms.CompareDescendingAtoms);
                Assert.Same(greatest.Monomial, top.Monomial);
                Assert.Equal(greatest.Coefficient, top.Coefficient);
                if (Monomial.TryDivide(top.Monomial, lead.Monomial) is { } q)
                {
                    // a division step: subtract the multiple of s whose leading product cancels the top term
                    var multiple = new Term(top.Coefficient / lead.Coefficient, q);
                    dividend.SubtractMultiple(multiple, s, lead.Monomial, top.Monomial);
                    expected -= Scalar.FromTerm(multiple.Coefficient, multiple.Monomial) * s;
                }
                else
                {
                    // a remainder step: the top term leaves the dividend
                    dividend.Remove(top.Monomial);
                    expected -= Scalar.FromTerm(top.Coefficient, top.Monomial);
                }
                Assert.Equal(expected.TermArray.Length, dividend.Count);
            }
        }
    }

    [Fact]
    public void Division_with_remainder_rebuilds_the_dividend_and_leaves_no_divisible_term()
    {
        var random = new Random(42);
        for (var trial = 0; trial < 80; trial++)
        {
            var s = RandomPolynomial(random, 2 + random.Next(3), 2);
            var b = RandomPolynomial(random, 1 + random.Next(4), 2) * s + RandomPolynomial(random, random.Next(6), 3);
            if (s.IsConstant || Scalar.IsZero(b)) continue;
            foreach (var first in PolynomialRemainder.Candidates(s))
            {
                if (!PolynomialRemainder.TryDivide(b, s, first, out var q, out var r)) continue;
                Assert.Same(b, q * s + r);
            }
        }
    }
}
