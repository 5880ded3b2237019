using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>inverse(1 + e1) is known at generation to be no versor: an error, not Ã/⟨AÃ⟩₀ written silently.</summary>
public sealed class MacroCodeGenerator_InverseOfConstants
{
    private const string Source = """
        define macro Bad as
            inputs: { x : e3d.Vector }
            outputs: { y : e3d.Multivector }
            performs:
                y = x gp inverse(1 + e3d.multivector { e1 : 1 });
        end macro
        define macro Good as
            inputs: { x : e3d.Vector }
            outputs: { y : e3d.Multivector }
            performs:
                y = x gp inverse(e3d.multivector { e1 : 1; e2 : 2 });
        end macro
        """;

    private static MacroCodeGenerator Generator() =>
        new(DslProject.FromSources([("test.gmac", Source), ("prelude.gmac", DslSnippets.E3d)]));

    [Fact]
    public void Inverse_of_a_constant_non_versor_is_a_generation_error()
    {
        var generator = Generator();
        var outcome = generator.Generate("Bad", generator.DefaultBindings("Bad"));
        var error = Assert.Single(outcome.Errors);
        Assert.Equal("GMAC0310", error.Code);
        Assert.Contains("is not a versor or blade", error.Message);
    }

    [Fact]
    public void Inverse_of_a_constant_vector_generates()
    {
        var generator = Generator();
        var outcome = generator.Generate("Good", generator.DefaultBindings("Good"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
    }
}
