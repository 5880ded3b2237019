using GMac.Core.Algebra;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>
/// 'vee', rcomplement and lcomplement bind and evaluate in a degenerate frame; dual and undual there
/// are GMAC0118 at the call, naming what works instead.
/// </summary>
public sealed class Binder_RegressiveAndComplements
{
    private const string Pga = """
        define frame p3 as basis: {e0, e1, e2, e3} signature {e0: 0, e1: 1, e2: 1, e3: 1} end frame
        define subspace p3.vectors as basis {e0, e1, e2, e3} end subspace
        define multivector class p3.Vector as vectors end multivector class
        """;

    [Theory]
    [InlineData("dual")]
    [InlineData("undual")]
    public void Dual_in_a_degenerate_frame_is_an_error_at_the_call_naming_the_complements(string function)
    {
        var d = MarkedSource.AssertSingle($$"""
            define macro M as
                inputs: { a : p3.Multivector }
                outputs: { y : p3.Multivector }
                performs:
                    y = «{{function}}(a)»;
            end macro
            """, "GMAC0118", Pga);
        Assert.Contains($"'{function}' needs an invertible metric, but frame 'p3' is degenerate", d.Message);
        Assert.Contains("rcomplement(A)", d.Message);
        Assert.Contains("'vee'", d.Message);
    }

    [Fact]
    public void Dual_in_an_invertible_frame_is_still_the_dual()
    {
        var project = SingleFileProject.Bind(DslSnippets.E3d + "\n" + """
            define macro M as
                inputs: { a : e3d.Vector }
                outputs: { y : e3d.Multivector }
                performs:
                    y = dual(a) + undual(a);
            end macro
            """);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
    }

    [Fact]
    public void Vee_sits_with_the_product_words_and_complements_evaluate_like_the_core_algebra()
    {
        var project = SingleFileProject.Bind(Pga + "\n" + """
            define macro M as
                inputs: { a : p3.Multivector; b : p3.Multivector; c : p3.Vector }
                outputs: { y : p3.Multivector; r : p3.Multivector; l : p3.Multivector }
                performs:
                    y = a vee b op c;
                    r = rcomplement(a);
                    l = lcomplement(a);
            end macro
            """);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
        var outputs = SymbolicMacro.Compile(project.Model.Macros["M"]).ToDictionary(o => o.Key.Name, o => o.Value);
        var frame = outputs["y"].Frame;
        var random = new Random(3);
        var values = new Dictionary<string, double>();
        Multivector<double> Random(string name, IEnumerable<int> ids) => Multivector<double>.FromTerms(frame, ids.Select(id =>
        {
            var blade = new BasisBlade(id);
            var v = random.NextDouble() * 2 - 1;
            values[SymbolicMultivector.VariableName(frame, name, blade)] = v;
            return (blade, v);
        }));
        var a = Random("a", Enumerable.Range(0, frame.BladeCount));
        var b = Random("b", Enumerable.Range(0, frame.BladeCount));
        var c = Random("c", [1, 2, 4, 8]);
        Close(a.Regressive(b).Op(c), outputs["y"].Evaluate(values));
        Close(a.RightComplement(), outputs["r"].Evaluate(values));
        Close(a.LeftComplement(), outputs["l"].Evaluate(values));
    }

    private static void Close(Multivector<double> expected, Multivector<double> actual)
    {
        for (var id = 0; id < expected.Frame.BladeCount; id++)
            Assert.Equal(expected[new BasisBlade(id)], actual[new BasisBlade(id)], 12);
    }
}
