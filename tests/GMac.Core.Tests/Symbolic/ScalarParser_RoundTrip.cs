using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class ScalarParser_RoundTrip
{
    [Theory]
    [InlineData("2*x*y - sin(a)^2")]
    [InlineData("1/2*x")]
    [InlineData("x/(a + b)")]
    [InlineData("(a + b)^(-3) + 1/x^2")]
    [InlineData("-x^3 + 2.5e-1*u.e1 - 7")]
    [InlineData("atan2(y, x) + pow(x, y) + abs(x - y) + exp(-x) + log(x + 1) + tan(2*x) + sqrt(x)")]
    [InlineData("cos(pi*t)/sqrt(x^2 + y^2) - 3/4*pi")]
    [InlineData("pow(-x, 1/3) * (x + y)^(-2) / sin(x)")]
    public void Printed_text_parses_back_to_the_same_object(string text)
    {
        var parsed = Scalar.Parse(text);
        var printed = parsed.ToString();
        Assert.Same(parsed, Scalar.Parse(printed));
        Assert.Equal(printed, Scalar.Parse(printed).ToString());
    }

    [Fact]
    public void Shared_text_parses_back_to_the_same_object()
    {
        var trees = new RandomExpressionTrees(seed: 5);
        for (var i = 0; i < 300; i++)
        {
            var s = trees.Next(depth: 5).Symbolic;
            var shared = ScalarPrinter.FormatShared(s);
            Assert.Same(s, ScalarParser.ParseShared(shared));
            Assert.Same(s, ScalarParser.ParseShared(s.ToString())); // plain text is a shared text without definitions
        }
    }

    [Fact]
    public void Shared_text_names_each_function_and_inverse_once()
    {
        var x = Scalar.Variable("x");
        var y = Scalar.Variable("y");
        var inverse = Scalar.One / (x + y);
        var s = x * inverse + y * inverse * inverse + Scalar.Sqrt(x * inverse + Scalar.One);
        Assert.Equal("$0 = 1/(x + y); $1 = sqrt(1 + x*$0); x*$0 + y*$0^2 + $1", ScalarPrinter.FormatShared(s));
    }

    [Theory]
    [InlineData("$0 = x; $2 = y; $0")]
    [InlineData("$0 = x + ; $0")]
    [InlineData("$0 = x; $1 + $0")]
    public void Malformed_shared_text_is_refused(string text)
    {
        Assert.ThrowsAny<FormatException>(() => ScalarParser.ParseShared(text));
    }

    [Fact]
    public void Numbers_are_exact()
    {
        Assert.Same(Scalar.Constant(new Rational(5, 4)), Scalar.Parse("1.25"));
        Assert.Same(Scalar.Constant(new Rational(1, 500)), Scalar.Parse("2e-3"));
        Assert.Same(Scalar.Constant(new Rational(1, 3)), Scalar.Parse("1/3"));
        Assert.Same(Scalar.Constant(-8), Scalar.Parse("-2^3"));
        Assert.Same(Scalar.Constant(new Rational(1, 8)), Scalar.Parse("2^-3"));
        Assert.Same(Scalar.Constant(512), Scalar.Parse("2^3^2"));
    }

    [Fact]
    public void Printed_form_is_conventional()
    {
        var x = Scalar.Variable("x");
        var y = Scalar.Variable("y");
        var a = Scalar.Variable("a");
        Assert.Equal("2*x*y - sin(a)^2", (Scalar.Scale(x * y, 2) - Scalar.Sin(a) * Scalar.Sin(a)).ToString());
        Assert.Equal("1/2*x", (x / 2).ToString());
        Assert.Equal("-x/y", (-x / y).ToString());
        Assert.Equal("1/(x + y)", (Scalar.One / (x + y)).ToString());
        Assert.Equal("0", Scalar.Zero.ToString());
    }

    [Theory]
    [InlineData("x + * y", 5)]
    [InlineData("sin(x", 6)]
    [InlineData("foo(x)", 1)]
    [InlineData("2x", 2)]
    [InlineData("x $ y", 3)]
    [InlineData("atan2(x)", 1)]
    [InlineData("", 1)]
    [InlineData("(x + y))", 8)]
    [InlineData("x / 0", 5)]
    [InlineData("1e+", 2)]
    [InlineData("pow(0, -1)", 1)]
    [InlineData("(x - x)^(-2)", 1)]
    [InlineData("2^100000", 3)]
    [InlineData("1e99999", 2)]
    public void Syntax_errors_carry_the_column(string text, int column)
    {
        var error = Assert.Throws<ScalarSyntaxException>(() => Scalar.Parse(text));
        Assert.Equal(column, error.Column);
        Assert.StartsWith($"column {column}: ", error.Message);
        Assert.False(Scalar.TryParse(text, out _));
    }

    [Fact]
    public void Deep_nesting_is_an_error_not_a_crash()
    {
        var text = new string('(', 100_000) + "x" + new string(')', 100_000);
        var error = Assert.Throws<ScalarSyntaxException>(() => Scalar.Parse(text));
        Assert.Contains("nested", error.Message);
        Assert.Same(Scalar.Variable("x"), Scalar.Parse(new string('(', 50) + "x" + new string(')', 50)));
    }
}
