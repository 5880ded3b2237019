using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

public class MacroCodeGenerator_Library
{
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() => new MacroCodeGenerator(DslProject.Load(RepositoryPaths.DslLibrary)));

    private static CoefficientBindingSpec Bind(string key, string value, int line = 1)
    {
        var dot = key.IndexOf('.');
        return new CoefficientBindingSpec(key[..dot], key[(dot + 1)..], value, true, line, 1);
    }

    private static GenerationOutcome Generate(string macro, params BindingSpec[] bindings) => Generator.Value.Generate(macro, bindings);

    [Fact]
    public void Get_normal_to_vectors_as_in_the_thesis_three_assignments_six_products_three_subtractions()
    {
        var outcome = Generate("GetNormalToVectors",
            Bind("u.e1", "<u.x>"), Bind("u.e2", "<u.y>"), Bind("u.e3", "<u.z>"),
            Bind("v.e1", "<v.x>"), Bind("v.e2", "<v.y>"), Bind("v.e3", "<v.z>"),
            Bind("w.e1", "<wx>"), Bind("w.e2", "<wy>"), Bind("w.e3", "<wz>"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.Equal((6, 3, 0), (s.Multiplications, s.Additions, s.Temporaries));
        Assert.Equal(
            "wx = u.y * v.z - u.z * v.y;\nwy = u.z * v.x - u.x * v.z;\nwz = u.x * v.y - u.y * v.x;\n",
            CSharpEmitter.Emit(outcome.Result.Block));
    }

    [Fact]
    public void Hidden_surface_is_two_products_and_five_subtractions()
    {
        // (v2 - v1) ∧ (v3 - v1) in the plane: the cross-product form with its five differences (thesis §4.12.3).
        var outcome = Generate("HiddenSurface",
            Bind("v1.e1", "<a.x>"), Bind("v1.e2", "<a.y>"), Bind("v2.e1", "<b.x>"), Bind("v2.e2", "<b.y>"),
            Bind("v3.e1", "<c.x>"), Bind("v3.e2", "<c.y>"), Bind("s.1", "<area>"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.Equal(2, s.Multiplications);
        Assert.Equal(5, s.Additions);
        Assert.Equal(0, s.Divisions);
    }

    [Fact]
    public void Rotor_to_matrix_with_the_normalized_rotor_class_has_reduced_diagonals()
    {
        var outcome = Generate("RotorToMatrix",
            Bind("r.1", "<R.w>"), Bind("r.e2^e3", "<R.x>"), Bind("r.e3^e1", "<R.y>"), Bind("r.e1^e2", "<R.z>"),
            Bind("c1.e1", "<m11>"), Bind("c2.e2", "<m22>"), Bind("c3.e3", "<m33>"), Bind("c1.e2", "<m21>"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var code = CSharpEmitter.Emit(outcome.Result!.Block);
        // 1 − 2(y² + z²) with the 2 taken by doubled operands: 1 − y·2y − z·2z
        Assert.Matches(@"m11 = 1\.0 - tmp\d+ - tmp\d+;", code);
        Assert.Matches(@"m22 = 1\.0 - tmp\d+ - tmp\d+;", code);
        Assert.Matches(@"m33 = 1\.0 - tmp\d+ - tmp\d+;", code);
        Assert.DoesNotContain("2.0 *", code);
        Assert.DoesNotContain("R.w * R.w", code);
    }

    [Fact]
    public void Sphere_through_four_points_at_most_one_hundred_operations()
    {
        var bindings = new List<BindingSpec>();
        foreach (var p in new[] { "p1", "p2", "p3", "p4" })
            bindings.Add(new ClassBindingSpec(p, "ConformalPoint3D", p, 1, 1));
        foreach (var b in new[] { "no", "e1", "e2", "e3", "ni" })
            bindings.Add(Bind($"omega.{b}", $"<s_{b}>"));
        var outcome = Generate("SphereThroughPoints", bindings.ToArray());
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        Assert.True(outcome.Result!.Statistics.Operations <= 100, outcome.Result.Statistics.ToString());
    }

    [Fact]
    public void Full_twist_fewer_operations_than_figure_66()
    {
        var outcome = Generate("ApplyTwistToPoint3D",
            new ClassBindingSpec("rot_axis", "Vector3D", "Axis", 1, 1),
            new ClassBindingSpec("tr_origin", "Vector3D", "AxisOrigin", 1, 1),
            new CoefficientBindingSpec("angle", "1", "cr", false, 1, 1),
            new CoefficientBindingSpec("tr_param", "1", "ct", false, 1, 1),
            new ClassBindingSpec("in_mv", "Vector3D", "p", 1, 1),
            new CoefficientBindingSpec("out_mv", "e1", "x", false, 1, 1),
            new CoefficientBindingSpec("out_mv", "e2", "y", false, 1, 1),
            new CoefficientBindingSpec("out_mv", "e3", "z", false, 1, 1));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        // Figure 6-6: 34 additions, 40 multiplications, 16 divisions, 17 calls = 107 operations
        Assert.True(s.Operations < 107, $"{s}\n{CSharpEmitter.Emit(outcome.Result.Block)}");
    }
}
