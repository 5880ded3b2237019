using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// log and sqrt of a multivector in the DSL: of a rotor they are the versor functions, of a scalar
/// the scalar ones; odd operands are a type error at the call; exp, log and sqrt outside their
/// domain (a 6D bivector, the log of a boost) are GMAC0320 at the call in the DSL.
/// </summary>
public sealed class MacroCodeGenerator_VersorFunctions
{
    private const string Source = """
        define frame e6 as basis: {e1, e2, e3, e4, e5, e6} Euclidean end frame
        define subspace e6.bivectors as basis {e1^e2, e3^e4, e5^e6, e1^e3} end subspace
        define multivector class e6.Bivector as bivectors end multivector class
        define frame m2 as basis: {t, x} signature (1, 1) end frame
        define subspace m2.even as basis {1, t^x} end subspace
        define multivector class m2.Even as even end multivector class
        define subspace e3d.rotors as basis {1, e1^e2, e2^e3, e1^e3} end subspace
        define multivector class e3d.Rotor as rotors end multivector class
        define macro Half as
            inputs: { r : e3d.Rotor; s : e3d.Scalar }
            outputs: { b : e3d.Multivector; h : e3d.Multivector; l : e3d.Multivector }
            performs:
                b = log(r);
                h = sqrt(r);
                l = log(s) + sqrt(s);
        end macro
        define macro Exp6 as
            inputs: { b : e6.Bivector }
            outputs: { r : e6.Multivector }
            performs:
                r = exp(b);
        end macro
        define macro LogBoost as
            inputs: { m : m2.Even }
            outputs: { b : m2.Multivector }
            performs:
                b = log(m);
        end macro
        """;

    private static MacroCodeGenerator Generator() =>
        new(DslProject.FromSources([("test.gmac", Source), ("prelude.gmac", DslSnippets.E3d)]));

    [Fact]
    public void Log_and_sqrt_of_a_rotor_are_versor_functions_and_of_a_scalar_scalar_functions()
    {
        var generator = Generator();
        var outcome = generator.Generate("Half", generator.DefaultBindings("Half"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        // The scalar log and sqrt of s are calls in the code; log(r) adds atan2.
        var code = string.Join("\n", outcome.Result!.Block.Statements.Select(st => st.ToString()));
        Assert.Contains("atan2", code);
        Assert.Contains("log", code);
    }

    [Theory]
    [InlineData("log")]
    [InlineData("sqrt")]
    public void Log_or_sqrt_of_a_vector_is_a_type_error_at_the_call(string function)
    {
        var d = MarkedSource.AssertSingle($$"""
            define macro M as
                inputs: { a : e3d.Vector }
                outputs: { y : e3d.Multivector }
                performs:
                    y = «{{function}}(a)»;
            end macro
            """, "GMAC0116", DslSnippets.E3d);
        Assert.Contains("rotor or motor", d.Message);
    }

    [Theory]
    [InlineData("Exp6", 21, "5D")]
    [InlineData("LogBoost", 27, "square to ≤ 0")]
    public void Exp_or_log_outside_its_domain_is_reported_at_the_call(string macro, int line, string message)
    {
        var generator = Generator();
        var outcome = generator.Generate(macro, generator.DefaultBindings(macro));
        var error = Assert.Single(outcome.Errors);
        Assert.Equal("GMAC0320", error.Code);
        Assert.Contains(message, error.Message);
        var at = Assert.IsType<Dsl.Diagnostics.SourceSpan>(error.Cause);
        Assert.Equal(("test.gmac", line), (at.FilePath, at.Line));
    }
}
