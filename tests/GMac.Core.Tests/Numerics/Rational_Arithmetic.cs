using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Tests.Numerics;

public class Rational_Arithmetic
{
    private static readonly Random Seeded = new(20261123);

    private static Rational RandomRational(Random random) =>
        new(random.Next(-1000, 1001), random.Next(1, 200));

    [Fact]
    public void Field_operations_agree_with_doubles()
    {
        for (var i = 0; i < 500; i++)
        {
            var a = RandomRational(Seeded);
            var b = RandomRational(Seeded);
            double x = a.ToDouble(), y = b.ToDouble();
            Assert.Equal(x + y, (a + b).ToDouble(), 12);
            Assert.Equal(x - y, (a - b).ToDouble(), 12);
            Assert.Equal(x * y, (a * b).ToDouble(), 9);
            if (!b.IsZero) Assert.Equal(x / y, (a / b).ToDouble(), 9);
        }
    }

    [Fact]
    public void Field_axioms_hold_exactly()
    {
        for (var i = 0; i < 300; i++)
        {
            var a = RandomRational(Seeded);
            var b = RandomRational(Seeded);
            var c = RandomRational(Seeded);
            Assert.Equal(a * (b + c), a * b + a * c);
            Assert.Equal((a + b) + c, a + (b + c));
            Assert.Equal(Rational.Zero, a - a);
            if (!a.IsZero) Assert.Equal(Rational.One, a * a.Reciprocal());
        }
    }

    [Fact]
    public void Values_are_kept_in_lowest_terms_with_positive_denominator()
    {
        var r = new Rational(6, -4);
        Assert.Equal(new BigInteger(-3), r.Numerator);
        Assert.Equal(new BigInteger(2), r.Denominator);
        Assert.Equal(new Rational(-3, 2), r);
        Assert.Equal(r.GetHashCode(), new Rational(-9, 6).GetHashCode());
    }

    [Fact]
    public void Division_by_zero_throws()
    {
        Assert.Throws<DivideByZeroException>(() => Rational.One / Rational.Zero);
        Assert.Throws<DivideByZeroException>(() => new Rational(1, 0));
    }

    [Fact]
    public void From_double_is_exact_for_random_doubles_of_every_magnitude()
    {
        for (var i = 0; i < 1000; i++)
        {
            var value = (Seeded.NextDouble() - 0.5) * Math.Pow(2, Seeded.Next(-1070, 1020));
            Assert.Equal(value, Rational.FromDouble(value).ToDouble());
        }
        Assert.Equal(double.Epsilon, Rational.FromDouble(double.Epsilon).ToDouble());
        Assert.Equal(new Rational(1, 1024), Rational.FromDouble(1.0 / 1024));
        Assert.Throws<ArgumentOutOfRangeException>(() => Rational.FromDouble(double.NaN));
    }

    [Fact]
    public void To_double_of_parts_beyond_the_range_of_a_double_is_their_ratio()
    {
        var big = BigInteger.Pow(10, 400);
        Assert.Equal(2.0 / 3.0, new Rational(2 * big + 1, 3 * big).ToDouble(), 15);
        Assert.Equal(-3e-310, new Rational(-3, BigInteger.Pow(10, 310)).ToDouble());
        Assert.Equal(1e-320, new Rational(1, BigInteger.Pow(10, 320)).ToDouble());
        Assert.Equal(0.0, new Rational(1, BigInteger.Pow(10, 5000)).ToDouble());
        Assert.Equal(double.PositiveInfinity, new Rational(BigInteger.Pow(10, 5000), 3).ToDouble());
    }

    [Theory]
    [InlineData("3", 3, 1)]
    [InlineData("-2/7", -2, 7)]
    [InlineData("1.25", 5, 4)]
    [InlineData("2.5e-3", 1, 400)]
    [InlineData("-1.5E2", -150, 1)]
    [InlineData("0.1", 1, 10)]
    [InlineData(" 4/-6 ", -2, 3)]
    public void Parse_reads_decimals_and_fractions_exactly(string text, int numerator, int denominator)
    {
        Assert.Equal(new Rational(numerator, denominator), Rational.Parse(text));
    }

    [Theory]
    [InlineData("")]
    [InlineData("-")]
    [InlineData("1/0")]
    [InlineData("1e")]
    [InlineData("abc")]
    [InlineData("1.2.3")]
    [InlineData("1e999999999")]
    [InlineData("1e-999999999")]
    [InlineData("1.5e-2147483648")]
    public void Try_parse_refuses_malformed_or_unbounded_text(string text)
    {
        Assert.False(Rational.TryParse(text, out _));
    }

    [Fact]
    public void Try_parse_accepts_exponents_up_to_the_stated_limit()
    {
        Assert.True(Rational.TryParse($"1e{Rational.MaxDecimalExponent}", out var big));
        Assert.Equal(BigInteger.Pow(10, Rational.MaxDecimalExponent), big.Numerator);
        Assert.True(Rational.TryParse($"1e-{Rational.MaxDecimalExponent}", out var small));
        Assert.Equal(BigInteger.Pow(10, Rational.MaxDecimalExponent), small.Denominator);
        Assert.False(Rational.TryParse($"1e{Rational.MaxDecimalExponent + 1}", out _));
    }

    [Fact]
    public void To_string_round_trips_through_parse()
    {
        for (var i = 0; i < 200; i++)
        {
            var r = RandomRational(Seeded);
            Assert.Equal(r, Rational.Parse(r.ToString()));
        }
    }

    [Fact]
    public void Pow_and_exact_sqrt_are_inverse()
    {
        var r = new Rational(-7, 3);
        Assert.Equal(new Rational(49, 9), r.Pow(2));
        Assert.Equal(new Rational(-27, 343), r.Pow(-3));
        Assert.True(r.Pow(2).TryExactSqrt(out var root));
        Assert.Equal(r.Abs(), root);
        Assert.False(new Rational(2, 1).TryExactSqrt(out _));
        Assert.False(new Rational(-4, 1).TryExactSqrt(out _));
        var huge = BigInteger.Pow(3, 301);
        Assert.True(new Rational(huge * huge, 4).TryExactSqrt(out var hugeRoot));
        Assert.Equal(new Rational(huge, 2), hugeRoot);
    }

    [Fact]
    public void Comparison_agrees_with_doubles()
    {
        for (var i = 0; i < 300; i++)
        {
            var a = RandomRational(Seeded);
            var b = RandomRational(Seeded);
            Assert.Equal(Math.Sign(a.ToDouble() - b.ToDouble()), Math.Sign(a.CompareTo(b)));
        }
    }
}
