using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

public class MacroCodeGenerator_Library
{
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() => new MacroCodeGenerator(DslProject.Load(RepositoryPaths.DslLibrary)));

    /// <summary>A coefficient bound to the one-hole template <c>"&lt;name&gt;"</c>.</summary>
    private static CoefficientBindingSpec Bind(string key, string name, int line = 1)
    {
        var dot = key.IndexOf('.');
        return new CoefficientBindingSpec(key[..dot], key[(dot + 1)..], BindingValues.Hole(name), line, 1);
    }

    private static GenerationOutcome Generate(string macro, params BindingSpec[] bindings) => Generator.Value.Generate(macro, bindings);

    [Fact]
    public void Hidden_surface_is_two_products_and_five_subtractions()
    {
        // (v2 - v1) ∧ (v3 - v1) in the plane: the cross-product form with its five differences (thesis §4.12.3).
        var outcome = Generate("HiddenSurface",
            Bind("v1.e1", "a.x"), Bind("v1.e2", "a.y"), Bind("v2.e1", "b.x"), Bind("v2.e2", "b.y"),
            Bind("v3.e1", "c.x"), Bind("v3.e2", "c.y"), Bind("s.1", "area"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.Equal(2, s.Multiplications);
        Assert.Equal(5, s.Additions);
        Assert.Equal(0, s.Divisions);
    }

    [Fact]
    public void Sphere_through_four_points_in_fewer_operations_than_by_hand()
    {
        var bindings = new List<BindingSpec>();
        foreach (var p in new[] { "p1", "p2", "p3", "p4" })
            bindings.Add(new ClassBindingSpec(p, "ConformalPoint3D", p, 1, 1));
        foreach (var b in new[] { "no", "e1", "e2", "e3", "ni" })
            bindings.Add(Bind($"omega.{b}", $"<s_{b}>"));
        var outcome = Generate("SphereThroughPoints", bindings.ToArray());
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        // the sphere through 0 and the differences to p1, moved back by p1: 80 operations (hand 81)
        Assert.True(outcome.Result!.Statistics.Operations <= 80, outcome.Result.Statistics.ToString());
    }

    [Fact]
    public void Plane_through_three_points_is_the_normal_of_the_differences_and_its_offset()
    {
        // n = (p2 − p1) × (p3 − p1) and δ = n·p1: 11 additions and 9 multiplications, as by hand
        var outcome = Generate("PlaneThroughPoints",
            new ClassBindingSpec("p1", "NormalizedPoint3D", "a", 1, 1), new ClassBindingSpec("p2", "NormalizedPoint3D", "b", 1, 1),
            new ClassBindingSpec("p3", "NormalizedPoint3D", "c", 1, 1), new ClassBindingSpec("dualPlane", "DualPlane3D", "dp", 1, 1));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.Equal((11, 9, 0), (s.Additions, s.Multiplications, s.Divisions));
    }

    [Fact]
    public void Full_twist_fewer_operations_than_figure_66()
    {
        var outcome = Generate("ApplyTwistToPoint3D",
            new ClassBindingSpec("rot_axis", "Vector3D", "Axis", 1, 1),
            new ClassBindingSpec("tr_origin", "Vector3D", "AxisOrigin", 1, 1),
            new CoefficientBindingSpec("angle", "1", BindingValues.Bare("cr"), 1, 1),
            new CoefficientBindingSpec("tr_param", "1", BindingValues.Bare("ct"), 1, 1),
            new ClassBindingSpec("in_mv", "Vector3D", "p", 1, 1),
            new CoefficientBindingSpec("out_mv", "e1", BindingValues.Bare("x"), 1, 1),
            new CoefficientBindingSpec("out_mv", "e2", BindingValues.Bare("y"), 1, 1),
            new CoefficientBindingSpec("out_mv", "e3", BindingValues.Bare("z"), 1, 1));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        // Figure 6-6: 34 additions, 40 multiplications, 16 divisions, 17 calls = 107 operations
        Assert.True(s.Operations < 107, $"{s}\n{outcome.Result.Block}");
    }
}
