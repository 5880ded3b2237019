using GMac.CSharp.BindingPoints;
using GMac.CSharp.Emit;
using GMac.CSharp.Tests.Support;
using GMac.Dsl.Generation;

namespace GMac.CSharp.Tests.Emit;

/// <summary>The C# printed for library macros of the thesis, with their bound names and targets.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class CSharpEmitter_LibraryMacros
{
    /// <summary>A coefficient bound to <c>"&lt;name&gt;"</c>, read as a //GMac.Bind line's quoted value is.</summary>
    private static CoefficientBindingSpec Bind(string key, string name)
    {
        var dot = key.IndexOf('.');
        return new CoefficientBindingSpec(key[..dot], key[(dot + 1)..], BindingValueReader.Read($"<{name}>", quoted: true), 1, 1);
    }

    private static GenerationOutcome Generate(string macro, params BindingSpec[] bindings) => SharedDsl.Context.Generator.Generate(macro, bindings);

    [Fact]
    public void Get_normal_to_vectors_as_in_the_thesis_three_assignments_six_products_three_subtractions()
    {
        var outcome = Generate("GetNormalToVectors",
            Bind("u.e1", "u.x"), Bind("u.e2", "u.y"), Bind("u.e3", "u.z"),
            Bind("v.e1", "v.x"), Bind("v.e2", "v.y"), Bind("v.e3", "v.z"),
            Bind("w.e1", "wx"), Bind("w.e2", "wy"), Bind("w.e3", "wz"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.Equal((6, 3, 0), (s.Multiplications, s.Additions, s.Temporaries));
        Assert.Equal(
            "wx = u.y * v.z - u.z * v.y;\nwy = u.z * v.x - u.x * v.z;\nwz = u.x * v.y - u.y * v.x;\n",
            CSharpEmitter.Emit(outcome.Result.Block));
    }

    [Fact]
    public void Rotor_to_matrix_with_the_normalized_rotor_class_has_reduced_diagonals()
    {
        var outcome = Generate("RotorToMatrix",
            Bind("r.1", "R.w"), Bind("r.e2^e3", "R.x"), Bind("r.e3^e1", "R.y"), Bind("r.e1^e2", "R.z"),
            Bind("c1.e1", "m11"), Bind("c2.e2", "m22"), Bind("c3.e3", "m33"), Bind("c1.e2", "m21"));
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var code = CSharpEmitter.Emit(outcome.Result!.Block);
        // 1 − 2(y² + z²) with the 2 taken by doubled operands: 1 − y·2y − z·2z
        Assert.Matches(@"m11 = 1\.0 - tmp\d+ - tmp\d+;", code);
        Assert.Matches(@"m22 = 1\.0 - tmp\d+ - tmp\d+;", code);
        Assert.Matches(@"m33 = 1\.0 - tmp\d+ - tmp\d+;", code);
        Assert.DoesNotContain("2.0 *", code);
        Assert.DoesNotContain("R.w * R.w", code);
    }
}
