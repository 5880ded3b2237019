using GMac.Core.Numerics;
using GMac.CSharp.BindingPoints;
using GMac.Dsl.Generation;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>The one reader of <c>//GMac.</c> lines: what each form becomes, and what it rejects.</summary>
public sealed class BindingLineReader_Lines
{
    /// <summary>Read as a comment, such a line would be replaced with the generated code and its binding lost without a word.</summary>
    [Theory]
    [InlineData("    // GMac.Bind(\"u.e1\", \"<a>\");")]
    [InlineData("    ///GMac.Bind(\"u.e1\", \"<a>\");")]
    [InlineData("    //Gmac.Bind(\"u.e1\", \"<a>\");")]
    public void Lines_that_only_look_like_binding_lines_are_errors(string line)
    {
        var read = BindingLineReader.Read(line, 3);
        Assert.NotNull(read);
        Assert.Null(read.Spec);
        Assert.Equal((3, 5), (read.Line, read.Column));
        Assert.Contains("looks like a GMac line", read.Error);
    }

    [Fact]
    public void Lines_without_the_prefix_are_not_binding_lines()
    {
        Assert.Null(BindingLineReader.Read("    // GMac: 12 operations", 3));
        Assert.Null(BindingLineReader.Read("x = 1; //GMac.Bind(\"u.e1\", \"<a>\");", 3));
        Assert.False(BindingLineReader.IsBindingLine("#region GMac : M"));
        Assert.True(BindingLineReader.IsBindingLine("\t //GMac.Anything"));
    }

    [Fact]
    public void Quoted_value_is_a_template_and_a_bare_expression_is_not()
    {
        var quoted = Spec<CoefficientBindingSpec>("        //GMac.Bind(\"u.e1^e2\", \"2\");\r\n", 7);
        Assert.Equal(("u", "e1^e2", "2", 7, 9), (quoted.Parameter, quoted.Blade, quoted.Value.Text, quoted.Line, quoted.Column));
        Assert.Equal([new ScalarTextPart("2")], Assert.IsType<TemplateValue>(quoted.Value).Parts);
        var bare = Spec<CoefficientBindingSpec>("//GMac.Bind(\"angle.1\", p.Angle * 2);", 1);
        Assert.Equal(("angle", "1", 1), (bare.Parameter, bare.Blade, bare.Column));
        Assert.Equal(new HostExpression("p.Angle * 2", HasEffects: false), bare.Value);
    }

    [Fact]
    public void String_arguments_are_read_with_csharp_escapes()
    {
        var verbatim = Spec<CoefficientBindingSpec>("//GMac.Bind(@\"u.e1\", \"<s[\\\"k\\\"]>\");", 1);
        Assert.Equal(("u", "e1", "<s[\"k\"]>"), (verbatim.Parameter, verbatim.Blade, verbatim.Value.Text));
    }

    [Fact]
    public void Class_binding_takes_a_string_or_bare_target()
    {
        var quoted = Spec<ClassBindingSpec>("//GMac.Bind(\"p\", \"Vector3D\", \"l.P1\"); // first point", 4);
        Assert.Equal(("p", "Vector3D", "l.P1"), (quoted.Parameter, quoted.ClassBinding, quoted.Target));
        var bare = Spec<ClassBindingSpec>("//GMac.Bind(\"p\", \"Vector3D\", l.P1)", 4);
        Assert.Equal("l.P1", bare.Target);
    }

    [Fact]
    public void Assumptions_become_bounds_with_their_direction()
    {
        var min = Spec<AssumptionSpec>("//GMac.AssumeMin(\"cr\", \"-1/2\");", 2);
        Assert.Equal(("cr", new Rational(-1, 2), true), (min.Expression, min.Value, min.IsMinimum));
        var max = Spec<AssumptionSpec>("//GMac.AssumeMax(p.Angle, 6.25);", 2);
        Assert.Equal(("p.Angle", new Rational(25, 4), false), (max.Expression, max.Value, max.IsMinimum));
    }

    [Theory]
    [InlineData("//GMac.Bind(\"u\", \"Vector3D\", u", "malformed binding line")]
    [InlineData("//GMac.Bind(\"u.e1\", \"<a>\") x", "malformed binding line")]
    [InlineData("//GMac.Bind(\"u\")", "takes 2 or 3 arguments")]
    [InlineData("//GMac.Bnd(\"u\", \"Vector3D\", u);", "unknown binding command 'GMac.Bnd'")]
    [InlineData("//GMac.Bind(u.e1, \"<a>\");", "must be a string \"parameter.blade\"")]
    [InlineData("//GMac.Bind(\"u.\", \"<a>\");", "must be a string \"parameter.blade\"")]
    [InlineData("//GMac.Bind(\"u.e1\", \"V\", u);", "takes a parameter name and a class binding name")]
    [InlineData("//GMac.AssumeMin(\"a\", \"zero\");", "the bound 'zero' of GMac.AssumeMin is not a number")]
    [InlineData("//GMac.AssumeMax(\"a\");", "GMac.AssumeMax takes 2 arguments")]
    public void Malformed_lines_are_rejected_with_a_reason(string line, string reason)
    {
        var read = BindingLineReader.Read("  " + line, 5);
        Assert.NotNull(read);
        Assert.False(read.Succeeded);
        Assert.Null(read.Spec);
        Assert.Equal((5, 3), (read.Line, read.Column));
        Assert.Contains(reason, read.Error);
    }

    private static T Spec<T>(string line, int number) where T : BindingSpec
    {
        var read = BindingLineReader.Read(line, number);
        Assert.NotNull(read);
        Assert.True(read.Succeeded, read.Error);
        return Assert.IsType<T>(read.Spec);
    }
}
