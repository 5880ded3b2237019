using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>
/// A flat sum is not nesting: one of thousands of terms binds and evaluates to the sum written,
/// whatever the mix of signs, without exhausting the stack of any stage that walks it.
/// </summary>
public sealed class Binder_FlatSums
{
    [Theory]
    [InlineData(2001)]
    [InlineData(20_000)]
    public void A_flat_sum_of_thousands_of_terms_evaluates_to_the_sum_written(int count)
    {
        // Signs in a pattern that is not periodic in powers of two, so every split of the sum mixes them;
        // products and brackets in the terms nest only within their term.
        var terms = Enumerable.Range(0, count).Select(i => (i % 3, i % 7 == 0)).ToList();
        var text = string.Concat(terms.Select((t, i) =>
            (i == 0 ? (t.Item2 ? "-" : "") : t.Item2 ? " - " : " + ") + (t.Item1 switch { 0 => "u", 1 => "2 * v", _ => "(x)" })));
        var project = SingleFileProject.Bind(DslSnippets.E3d + $$"""

            define macro S as
                inputs: { u : e3d.Vector; v : e3d.Vector; x : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
                    w = {{text}};
            end macro
            """);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
        var macro = project.Model.Macros["S"];

        var frames = new CoreFrames();
        var inputs = SymbolicMacro.Inputs(frames, macro);
        var w = new MacroCompiler(frames).Evaluator.Evaluate(macro, inputs).Single().Value;

        // Each input's count, minus the count of its negated occurrences twice over.
        int Weight(int which) => terms.Count(t => t.Item1 == which) - 2 * terms.Count(t => t.Item1 == which && t.Item2);
        var (u, v, x) = (inputs[macro.Inputs[0]], inputs[macro.Inputs[1]], inputs[macro.Inputs[2]]);
        for (var id = 0; id < w.Frame.BladeCount; id++)
        {
            var blade = new BasisBlade(id);
            var expected = (Scalar)Weight(0) * u[blade] + 2 * Weight(1) * v[blade] + Weight(2) * x[blade];
            Assert.Equal(expected, w[blade]);
        }
    }
}
