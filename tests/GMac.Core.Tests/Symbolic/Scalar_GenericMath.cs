using System.Numerics;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class Scalar_GenericMath
{
    // Written once over T, as Multivector<T> is, and run with double and with Scalar.
    private static T Formula<T>(T x, T y)
        where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>,
                  IExponentialFunctions<T>, ILogarithmicFunctions<T>, IPowerFunctions<T>
    {
        var half = T.CreateChecked(0.5);
        var three = T.CreateChecked(3);
        return T.Sinh(x) * T.Cosh(y) - T.Tanh(x * y) + T.Hypot(x, y) + T.CosPi(x) * T.SinPi(y) + T.TanPi(x / three)
             + T.Exp2(y) + T.Exp10(half * x) + T.ExpM1(x) + T.Log10(x) + T.Log2(y) + T.Log(x, three) + T.LogP1(y)
             + T.Cbrt(-y) + T.RootN(x, 5) + T.Sqrt(x + y) + T.Pow(x, y) + T.Pow(y, half)
             + T.Atan(x) + T.Acos(x / three) + T.Asin(y / three) + T.AtanPi(y) + T.Asinh(y) + T.Acosh(x + three) + T.Atanh(y / three)
             + T.DegreesToRadians(x) + T.RadiansToDegrees(y) + T.Abs(x - y) + T.Exp(x) * T.Log(y) + T.Tan(x) - T.Sin(y) * T.Cos(x)
             + T.MultiplicativeIdentity - T.AdditiveIdentity;
    }

    [Fact]
    public void A_formula_written_over_t_agrees_for_double_and_scalar()
    {
        var symbolic = Formula(Scalar.Variable("x"), Scalar.Variable("y"));
        var random = new Random(3);
        for (var k = 0; k < 20; k++)
        {
            double x = 0.2 + random.NextDouble(), y = 0.1 + random.NextDouble();
            var expected = Formula(x, y);
            var actual = symbolic.Evaluate(new Dictionary<string, double> { ["x"] = x, ["y"] = y });
            Assert.Equal(expected, actual, 1e-9 * Math.Max(1, Math.Abs(expected)));
        }
    }

    [Fact]
    public void Creation_from_other_number_types_is_exact()
    {
        Assert.Same(Scalar.Constant(7), Scalar.CreateChecked(7L));
        Assert.Same(Scalar.Constant(new Rational(1, 8)), Scalar.CreateChecked(0.125));
        Assert.Same(Scalar.Constant(new Rational(5, 4)), Scalar.CreateChecked(1.25m));
        Assert.Same(Scalar.Constant(BigInteger.Pow(10, 30)), Scalar.CreateChecked(BigInteger.Pow(10, 30)));
        Assert.Throws<OverflowException>(() => Scalar.CreateChecked(double.NaN));
        Assert.Equal(0.75, double.CreateChecked(Scalar.Constant(new Rational(3, 4))));
        Assert.Throws<NotSupportedException>(() => double.CreateChecked(Scalar.Variable("x")));
    }

    [Fact]
    public void Predicates_are_exact_for_constants_and_conservative_otherwise()
    {
        var x = Scalar.Variable("x");
        Assert.True(Scalar.IsNegative(Scalar.Constant(-2)));
        Assert.True(Scalar.IsPositive(Scalar.Constant(new Rational(1, 3))));
        Assert.True(Scalar.IsInteger(Scalar.Constant(4)) && Scalar.IsEvenInteger(Scalar.Constant(4)) && Scalar.IsOddInteger(Scalar.Constant(-3)));
        Assert.False(Scalar.IsNegative(x) || Scalar.IsPositive(x) || Scalar.IsInteger(x) || Scalar.IsFinite(x) || Scalar.IsNaN(x));
        Assert.True(Scalar.IsZero(x * x - x * x));
        Assert.False(Scalar.IsZero(Scalar.Sin(x) * Scalar.Sin(x) + Scalar.Cos(x) * Scalar.Cos(x) - Scalar.One));
        Assert.Same(Scalar.Constant(-5), Scalar.MaxMagnitude(Scalar.Constant(3), Scalar.Constant(-5)));
        Assert.Throws<NotSupportedException>(() => Scalar.MaxMagnitude(x, Scalar.One));
    }

    [Fact]
    public void Formatting_and_parsing_members_use_the_canonical_text()
    {
        var s = Scalar.Parse("2*x*y - sin(a)^2", System.Globalization.CultureInfo.InvariantCulture);
        Span<char> buffer = stackalloc char[64];
        Assert.True(s.TryFormat(buffer, out var written, default, null));
        Assert.Equal("2*x*y - sin(a)^2", buffer[..written].ToString());
        Assert.False(s.TryFormat(buffer[..3], out _, default, null));
        Assert.True(Scalar.TryParse("x^2".AsSpan(), null, out var square));
        Assert.Same(Scalar.Variable("x") * Scalar.Variable("x"), square);
    }
}
