using System.Text;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>
/// "Did you mean" compares an unknown name with every name in scope. Thousands of unknown names among
/// thousands of temporaries would take minutes; past a budget of comparisons every unknown name is
/// still reported, without a hint.
/// </summary>
public sealed class Binder_HintBudget
{
    [Fact]
    public void Past_the_budget_unknown_names_are_still_all_reported_but_without_a_hint()
    {
        // Unknown name i is compared with the i temporaries before it: n²/2 comparisons in all.
        const int n = 1500;
        Assert.True(n * (n / 2) > GMac.Dsl.Semantics.Binder.HintComparisons);
        var performs = new StringBuilder();
        for (var i = 0; i < n; i++) performs.Append($"t{i} = u;\nw = t{i} + q{i};\n");
        var project = SingleFileProject.Bind(DslSnippets.E3d + $$"""

            define macro M as
                inputs: { u : e3d.Vector }
                outputs: { w : e3d.Vector }
                performs:
            {{performs}}
            end macro
            """);

        var unknown = project.Diagnostics.Where(d => d.Code == "GMAC0101").ToList();
        Assert.Equal(n, unknown.Count);
        Assert.Equal("unknown multivector 'q0'; did you mean 't0'?", unknown[0].Message);
        Assert.Equal($"unknown multivector 'q{n - 1}'", unknown[^1].Message);
    }
}
