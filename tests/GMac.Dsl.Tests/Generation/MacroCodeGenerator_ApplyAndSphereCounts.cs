using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// The rotor and dual-sphere macros cost no more than their hand-written forms: a quaternion
/// rotation (t = q × v twice, 18 products and 12 sums; with a norm, 22, 15 and one division) and
/// centre = ω_E / α with r² = c² − 2 ω_ni / α (8 products, 3 sums, one division, one root).
/// </summary>
public sealed class MacroCodeGenerator_ApplyAndSphereCounts
{
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() => new MacroCodeGenerator(DslProject.Load(RepositoryPaths.DslLibrary)));

    [Theory]
    [InlineData("ApplyUnitRotor3D", 18, 12, 0, 0)]
    [InlineData("ApplyRotor3D", 22, 15, 1, 0)]
    [InlineData("SphereCentreAndRadius", 8, 3, 1, 1)]
    public void Costs_no_more_than_the_hand_written_form(string macro, int multiplications, int additions, int divisions, int calls)
    {
        var outcome = Generator.Value.Generate(macro, Generator.Value.DefaultBindings(macro));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.True(s.Multiplications <= multiplications && s.Additions <= additions && s.Divisions <= divisions && s.Calls <= calls,
            $"{macro}: {s}");
    }
}
