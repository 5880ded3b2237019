using GMac.Benchmarks.Accuracy;
using GMac.Core.Numerics;

namespace GMac.Benchmarks.Tests.Accuracy;

public class HighPrecision_Functions
{
    private static Rational R(double x) => Rational.FromDouble(x);

    /// <summary>|a − b| below 2^-150 of |b| (or of 1): far beyond what a double can tell apart.</summary>
    private static void AssertClose(Rational expected, Rational actual)
    {
        var scale = Rational.One + expected.Abs();
        Assert.True((expected - actual).Abs() * Rational.Parse("1427247692705959881058285969449495136382746624") <= scale,
            $"{expected.ToDouble():R} versus {actual.ToDouble():R}");
    }

    [Theory]
    [InlineData(0.3)]
    [InlineData(-2.5)]
    [InlineData(17.25)]
    public void Sine_and_cosine_agree_with_math_and_square_to_one(double x)
    {
        var s = HighPrecision.Sin(R(x));
        var c = HighPrecision.Cos(R(x));
        Assert.Equal(Math.Sin(x), s.ToDouble(), 15);
        Assert.Equal(Math.Cos(x), c.ToDouble(), 15);
        AssertClose(Rational.One, HighPrecision.Round(s * s + c * c));
    }

    [Fact]
    public void Square_root_squares_back_and_exact_roots_stay_exact()
    {
        var root = HighPrecision.Sqrt(R(2))!.Value;
        AssertClose(R(2), HighPrecision.Round(root * root));
        Assert.Equal(new Rational(3, 2), HighPrecision.Sqrt(new Rational(9, 4)));
        Assert.Null(HighPrecision.Sqrt(R(-1)));
    }

    [Fact]
    public void Exponential_and_logarithm_invert_each_other()
    {
        foreach (var x in new[] { 0.001, 0.7, 3.0, 40.0 })
        {
            var log = HighPrecision.Log(R(x))!.Value;
            Assert.Equal(Math.Log(x), log.ToDouble(), 14);
            AssertClose(R(x), HighPrecision.Exp(log));
        }
        Assert.Null(HighPrecision.Log(Rational.Zero));
    }

    [Fact]
    public void Arctangent_covers_the_four_quadrants_and_tangent_inverts_it()
    {
        foreach (var (y, x) in new[] { (1.0, 2.0), (3.0, -1.0), (-0.5, -4.0), (-2.0, 0.25), (1.0, 0.0) })
            Assert.Equal(Math.Atan2(y, x), HighPrecision.Atan2(R(y), R(x))!.Value.ToDouble(), 15);
        var angle = HighPrecision.Atan(new Rational(3, 7));
        AssertClose(new Rational(3, 7), HighPrecision.Call("tan", [angle])!.Value);
        Assert.Equal(Math.PI, HighPrecision.Pi.ToDouble());
    }

    [Fact]
    public void Arc_cosine_inverts_cosine_on_its_domain_and_is_undefined_beyond()
    {
        foreach (var x in new[] { -1.0, -0.75, 0.0, 0.3, 0.999999, 1.0 })
            Assert.Equal(Math.Acos(x), HighPrecision.Call("acos", [R(x)])!.Value.ToDouble(), 15);
        var angle = HighPrecision.Acos(new Rational(2, 9))!.Value;
        AssertClose(new Rational(2, 9), HighPrecision.Cos(angle));
        Assert.Null(HighPrecision.Acos(new Rational(9, 8)));
    }
}
