using GMac.Core.CodeGeneration.Accuracy;
using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// Gram–Schmidt by rejections as the report binds it. The textbook form (w2 = v2 − k v1,
/// n = v1 × v2) takes 40 operations and loses digits where the vectors share a large common part;
/// n = v1 × (v2 − v1) keeps them for three subtractions more and does not wait for the division
/// of k. The generator must find that form, not one that costs more.
/// </summary>
public class MacroCodeGenerator_GramSchmidtRejection
{
    [Fact]
    public void The_generated_form_costs_at_most_the_textbook_form_and_three_subtractions_and_is_accurate_on_vectors_with_a_large_common_part()
    {
        var generator = new MacroCodeGenerator(DslProject.Load(RepositoryPaths.DslLibrary));
        var bindings = new[] { "v1", "v2", "v3", "w1", "w2", "w3" }
            .Select(p => (BindingSpec)new ClassBindingSpec(p, "Vector3D", p, 1, 1)).ToArray();
        var outcome = generator.Generate("GramSchmidtRejection", bindings);
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.True(s.Operations <= 43 && s.Divisions == 2, s.ToString());
        // the probe's inputs all sit near 1e4: the textbook n = v1 × v2 is off there by about 1e-9
        Assert.InRange(AccuracyProbe.Error(outcome.Result.Block)!.Value, 0, 1e-14);
    }
}
