using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>Problems that only show once a binding point is generated are user errors with a position, not internal errors.</summary>
public sealed class MacroCodeGenerator_UserErrors
{
    private const string Source = """
        define binding V as
            use frame e3d
            bind { e1 : <x>; e2 : <y>; e3 : <z> }
            min { x : 5 }
        end binding
        define macro Norm2 as
            inputs: { u : e3d.Vector }
            outputs: { s : e3d.Scalar }
            performs:
                s = (u sp u).<1>;
        end macro
        define macro DivZero as
            inputs: { x : e3d.Vector }
            outputs: { w : e3d.Vector }
            performs:
                w = x / (x.<e1> - x.<e1>);
        end macro
        """;

    private static MacroCodeGenerator Generator() =>
        new(DslProject.FromSources([("test.gmac", Source), ("prelude.gmac", DslSnippets.E3d)]));

    private static CoefficientBindingSpec Bind(string parameter, string blade, BindingValue value, int line) =>
        new(parameter, blade, value, line, 3);

    [Fact]
    public void Assume_min_above_assume_max_is_reported_at_the_assumption_that_empties_the_bounds()
    {
        var outcome = Generator().Generate("Norm2",
        [
            Bind("u", "e1", BindingValues.Hole("a"), 2), Bind("s", "1", BindingValues.Hole("r"), 3),
            new AssumptionSpec("a", 3, true, 4, 5), new AssumptionSpec("a", 1, false, 5, 7),
        ]);
        var error = Assert.Single(outcome.Errors);
        Assert.Equal(("GMAC0312", 5, 7), (error.Code, error.Span.Line, error.Span.Column));
        Assert.Contains("'a'", error.Message);
    }

    [Fact]
    public void Assume_max_below_a_class_binding_minimum_is_reported_at_the_assumption()
    {
        var outcome = Generator().Generate("Norm2",
        [
            new ClassBindingSpec("u", "V", "obj", 2, 3), Bind("s", "1", BindingValues.Hole("r"), 3),
            new AssumptionSpec("obj.x", 1, false, 6, 9),
        ]);
        var error = Assert.Single(outcome.Errors);
        Assert.Equal(("GMAC0312", 6, 9), (error.Code, error.Span.Line, error.Span.Column));
    }

    [Fact]
    public void Binding_errors_are_placed_in_the_file_of_the_binding_point()
    {
        var outcome = Generator().Generate("Norm2", [Bind("u", "e4", BindingValues.Hole("a"), 12), Bind("s", "1", BindingValues.Hole("r"), 13)], regionLine: 11, filePath: "src/K.cs");
        var error = Assert.Single(outcome.Errors);
        Assert.Equal("src/K.cs(12,3): error GMAC0303: 'e4' is not a blade of frame 'e3d' (basis vectors: e1, e2, e3)", error.ToString());
    }

    [Fact]
    public void Consistent_assumptions_generate()
    {
        var outcome = Generator().Generate("Norm2",
        [
            Bind("u", "e1", BindingValues.Hole("a"), 2), Bind("u", "e2", BindingValues.Scalar("0"), 2), Bind("u", "e3", BindingValues.Scalar("0"), 2), Bind("s", "1", BindingValues.Hole("r"), 3),
            new AssumptionSpec("a", 1, true, 4, 5), new AssumptionSpec("a", 3, false, 5, 7),
        ]);
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
    }

    [Fact]
    public void Division_by_an_expression_that_simplifies_to_zero_is_reported_at_the_division_in_the_dsl()
    {
        var generator = Generator();
        var outcome = generator.Generate("DivZero", generator.DefaultBindings("DivZero"), regionLine: 9);
        var error = Assert.Single(outcome.Errors);
        Assert.Equal("GMAC0313", error.Code);
        Assert.Equal(9, error.Span.Line);
        var at = Assert.IsType<Dsl.Diagnostics.SourceSpan>(error.Cause);
        // The division "x / (x.<e1> - x.<e1>)" on line 16 of test.gmac, after "w = ".
        Assert.Equal(("test.gmac", 16, 13), (at.FilePath, at.Line, at.Column));
    }

    [Fact]
    public void Inverse_of_a_null_vector_is_reported_at_its_statement_in_the_dsl()
    {
        var project = DslProject.FromSources([
            ("frames.gmac", File.ReadAllText(Path.Combine(RepositoryPaths.DslLibrary, "frames.gmac"))),
            ("bad.gmac", """
                define subspace cga5d.vectors as basis {no, e1, e2, e3, ni} end subspace
                define multivector class cga5d.Vector as vectors end multivector class
                define macro Bad as inputs: { x : cga5d.Vector } outputs: { y : cga5d.Vector } performs:
                    y = x + inverse(cga5d.ni);
                end macro
                """)]);
        Assert.Empty(project.Diagnostics);
        var generator = new MacroCodeGenerator(project);
        var outcome = generator.Generate("Bad", generator.DefaultBindings("Bad"), regionLine: 7);
        var error = Assert.Single(outcome.Errors);
        Assert.Equal(7, error.Span.Line);
        var at = Assert.IsType<Dsl.Diagnostics.SourceSpan>(error.Cause);
        Assert.Equal(("bad.gmac", 4), (at.FilePath, at.Line));
    }
}
