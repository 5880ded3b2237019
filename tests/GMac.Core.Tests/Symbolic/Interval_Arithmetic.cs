using System.Numerics;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class Interval_Arithmetic
{
    [Fact]
    public void Exact_values_stay_points_and_others_are_enclosed_with_their_sign()
    {
        Assert.Equal(new Interval(0.25, 0.25), Interval.Exactly(new Rational(1, 4)));
        var third = Interval.Exactly(new Rational(1, 3));
        Assert.True(third.Lower < 1.0 / 3 && 1.0 / 3 < third.Upper);
        var tiny = Interval.Exactly(new Rational(BigInteger.One, BigInteger.Pow(10, 400)));
        Assert.True(tiny.IsNonNegative);
        var huge = Interval.Exactly(new Rational(-BigInteger.Pow(10, 400), 3));
        Assert.True(huge.IsNegative);
    }

    [Fact]
    public void Products_and_sums_with_zero_ends_stay_exact()
    {
        var nonNegative = new Interval(0, double.PositiveInfinity);
        Assert.Equal(0, (nonNegative * nonNegative).Lower);
        Assert.Equal(0, (nonNegative + nonNegative).Lower);
        Assert.Equal(0, new Interval(-3, 2).Power(2).Lower);
        Assert.Equal(new Interval(0, 0), new Interval(0, 0) * Interval.Everything);
    }

    [Fact]
    public void Reciprocals_keep_the_sign_and_straddling_zero_gives_everything()
    {
        Assert.True(new Interval(2, double.PositiveInfinity).Reciprocal().IsNonNegative);
        Assert.True(new Interval(double.NegativeInfinity, -2).Reciprocal().IsNonPositive);
        Assert.Equal(Interval.Everything, new Interval(-1, 1).Reciprocal());
    }

    [Fact]
    public void Random_operations_enclose_sampled_values()
    {
        var random = new Random(11);
        for (var n = 0; n < 2000; n++)
        {
            var a = RandomInterval(random);
            var b = RandomInterval(random);
            var x = a.Lower + (a.Upper - a.Lower) * random.NextDouble();
            var y = b.Lower + (b.Upper - b.Lower) * random.NextDouble();
            Assert.True((a + b).Contains(x + y));
            Assert.True((a * b).Contains(x * y));
            Assert.True(a.Power(3).Contains(x * x * x));
            Assert.True(a.Power(2).Contains(x * x));
            if (x != 0) Assert.True(a.Reciprocal().Contains(1 / x));
        }
    }

    private static Interval RandomInterval(Random random)
    {
        var p = (random.NextDouble() - 0.5) * 10;
        var q = (random.NextDouble() - 0.5) * 10;
        return new Interval(Math.Min(p, q), Math.Max(p, q));
    }
}
