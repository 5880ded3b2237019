using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// Errors found while a macro is evaluated for a binding point quote the expression as written in
/// the macro, with its parameter and blade names, and never the generator's temporaries (_gmac_t…),
/// input atoms (bp_in…) or the polynomials they stand in.
/// </summary>
public sealed class MacroCodeGenerator_MessagesInUserWords
{
    private const string Source = """
        define frame c3 as
            basis: {no, e1, ni}
            IPM = {{0, 0, -1}, {0, 1, 0}, {-1, 0, 0}}
        end frame
        define subspace c3.vectors as basis {no, e1, ni} end subspace
        define multivector class c3.Vector as vectors end multivector class
        define frame p3 as
            basis: {e0, e1, e2}
            signature {e0: 0, e1: 1, e2: 1}
        end frame
        define subspace p3.vectors as basis {e0, e1, e2} end subspace
        define multivector class p3.Vector as vectors end multivector class
        define macro NullInverse as
            inputs: { x : c3.Vector }
            outputs: { y : c3.Multivector }
            performs:
                t = x gp x;
                y = inverse(x.<e1>  *  c3.multivector { ni : 1 }) + t;
        end macro
        define macro NoGeneralInverse as
            inputs: { x : e3d.Vector }
            outputs: { y : e3d.Multivector }
            performs:
                y = general_inverse(x - x + 1 + e3d.multivector { e1 : 1 });
        end macro
        define macro DegenerateInverse as
            inputs: { p : p3.Vector }
            outputs: { y : p3.Multivector }
            performs:
                y = general_inverse(p.<e0> * p3.multivector { e0 : 1 });
        end macro
        define macro ExpOfMixedGrades as
            inputs: { x : e3d.Vector }
            outputs: { y : e3d.Multivector }
            performs:
                y = exp(x gp e3d.multivector { e1 : 1 } + x);
        end macro
        define macro DividesByZero as
            inputs: { x : e3d.Vector }
            outputs: { w : e3d.Vector }
            performs:
                w = x / (x.<e1> * x.<e2> - x.<e2> * x.<e1>);
        end macro
        """;

    private static MacroCodeGenerator Generator() =>
        new(DslProject.FromSources([("test.gmac", Source), ("prelude.gmac", DslSnippets.E3d)]));

    [Theory]
    [InlineData("NullInverse", "inverse(x.<e1> * c3.multivector { ni : 1 })", "GMAC0325")]
    [InlineData("NoGeneralInverse", "general_inverse(x - x + 1 + e3d.multivector { e1 : 1 })", "GMAC0325")]
    [InlineData("DegenerateInverse", "general_inverse(p.<e0> * p3.multivector { e0 : 1 })", "GMAC0325")]
    [InlineData("ExpOfMixedGrades", "exp(x gp e3d.multivector { e1 : 1 } + x)", "GMAC0320")]
    [InlineData("DividesByZero", "x / (x.<e1> * x.<e2> - x.<e2> * x.<e1>)", "GMAC0313")]
    public void The_message_quotes_the_expression_as_written(string macro, string expression, string code)
    {
        var generator = Generator();
        var outcome = generator.Generate(macro, generator.DefaultBindings(macro));
        var error = Assert.Single(outcome.Errors);
        Assert.Equal(code, error.Code);
        Assert.Contains($"'{expression}'", error.Message);
        Assert.DoesNotContain("_gmac_", error.Message);
        Assert.DoesNotContain("bp_in", error.Message);
    }
}
