using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class Cancellation_And_HalfAngles
{
    private static readonly Scalar X = Scalar.Variable("x"), Y = Scalar.Variable("y"), T = Scalar.Variable("t");

    [Fact]
    public void Exact_multiples_of_a_sum_cancel_against_its_inverse()
    {
        var q = X * X + Y * Y;
        Assert.Same(Scalar.One, InverseCancellation.Cancel(X * X / q + Y * Y / q));
        Assert.Same(X, InverseCancellation.Cancel((X * X * X + X * Y * Y) / q));
        // a remainder stays: nothing is cancelled
        var partial = (X * X + Y) / q;
        Assert.Same(partial, InverseCancellation.Cancel(partial));
    }

    [Fact]
    public void Cancellation_reaches_inside_denominators()
    {
        var q = X * X + Y * Y;
        var inner = q * T / q - T + 2; // = 2 once q/q cancels
        var value = Scalar.One / inner;
        Assert.Same(Scalar.Constant(new Core.Numerics.Rational(1, 2)), InverseCancellation.CancelDeep(value));
    }

    [Fact]
    public void Half_angle_products_become_full_angle_functions_with_the_same_value()
    {
        var u = T / 2;
        var value = Scalar.Cos(u) * Scalar.Cos(u) - Scalar.Sin(u) * Scalar.Sin(u) + 2 * Scalar.Sin(u) * Scalar.Cos(u) * X;
        var reduced = HalfAngleReduction.Apply(value);
        Assert.Same(Scalar.Cos(T) + Scalar.Sin(T) * X, reduced);
        var random = new Random(90);
        for (var i = 0; i < 10; i++)
        {
            var v = new Dictionary<string, double> { ["t"] = random.NextDouble() * 6 - 3, ["x"] = random.NextDouble() };
            Assert.Equal(value.Evaluate(v), reduced.Evaluate(v), 12);
        }
    }

    [Fact]
    public void Terms_with_one_sine_or_cosine_per_half_angle_stay_and_the_others_beside_them_reduce()
    {
        var (u, v) = (T / 2, X / 2);
        // sin u cos v and cos u · y: nothing to reduce, the value comes back as it is
        var plain = Scalar.Sin(u) * Scalar.Cos(v) + Scalar.Cos(u) * Y;
        Assert.Same(plain, HalfAngleReduction.Apply(plain));
        // beside a reducible term, those terms keep their factors (a negative power among them)
        var mixed = plain + Scalar.Sin(u) * Scalar.Sin(u) * Y / X;
        var reduced = HalfAngleReduction.Apply(mixed);
        Assert.Same(plain + (Scalar.One - Scalar.Cos(T)) / 2 * Y / X, reduced);
        var random = new Random(91);
        for (var i = 0; i < 10; i++)
        {
            var values = new Dictionary<string, double> { ["t"] = random.NextDouble() * 6 - 3, ["x"] = random.NextDouble() + 0.5, ["y"] = random.NextDouble() };
            Assert.Equal(mixed.Evaluate(values), reduced.Evaluate(values), 12);
        }
    }

    [Fact]
    public void Exact_division_finds_multiples_and_refuses_a_dividend_whose_powers_spread_less_than_the_divisors()
    {
        var s = X * X + Y;
        Assert.True(InverseCancellation.TryDivide((X + T) * s, s, out var q));
        Assert.Same(X + T, q);
        // x·y + 1 spreads over x⁰…x¹, the divisor over x⁰…x²: no multiple of it
        Assert.False(InverseCancellation.TryDivide(X * Y + 1, s, out _));
        // a divisor with a single power of an atom puts no bound on the dividend's spread in it
        var t = X * (Y + T);
        Assert.True(InverseCancellation.TryDivide(t * (Y + 1), t, out var r));
        Assert.Same(Y + 1, r);
    }
}
