using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// A macro that differentiates, itself or through any macro it calls, is generated joined only
/// (its derivative is taken of the whole expression); other macros try every form.
/// </summary>
public sealed class MacroCodeGenerator_DifferentiationForm
{
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() =>
    {
        var project = DslProject.FromSources([("prelude.gmac", DslSnippets.E3d), ("test.gmac", """
            define macro Moved as
                inputs: { u : e3d.Vector; t : e3d.Scalar }
                outputs: { x : e3d.Vector }
                performs: x = u gp t gp t + u;
            end macro
            define macro Rate as
                inputs: { u : e3d.Vector; t : e3d.Scalar }
                outputs: { r : e3d.Vector }
                performs: r = diff(Moved(u, t), t.<1>);
            end macro
            define macro Outer as
                inputs: { u : e3d.Vector; v : e3d.Vector; t : e3d.Scalar }
                outputs: { y : e3d.Vector }
                performs: y = Rate(u, t) + (u op v) lcp v;
            end macro
            define macro Plain as
                inputs: { u : e3d.Vector; v : e3d.Vector; t : e3d.Scalar }
                outputs: { y : e3d.Vector }
                performs: y = Moved(u, t) + (u op v) lcp v;
            end macro
            """)]);
        Assert.True(project.Diagnostics.All(d => !d.IsError), string.Join("\n", project.Diagnostics));
        return new MacroCodeGenerator(project);
    });

    private static CodeGenerationResult Generate(string macro)
    {
        var generator = Generator.Value;
        var outcome = generator.Generate(macro, generator.DefaultBindings(macro));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        return outcome.Result!;
    }

    [Theory]
    [InlineData("Rate")]
    [InlineData("Outer")]
    public void A_macro_that_reaches_a_derivative_has_only_the_joined_form(string macro)
    {
        var result = Generate(macro);
        Assert.Equal(JoinMode.Joined, result.Form);
        Assert.Null(result.Alternative);
    }

    [Fact]
    public void A_macro_without_a_derivative_compares_forms()
    {
        Assert.NotNull(Generate("Plain").Alternative);
    }
}
