using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>A binding point that binds only inputs writes every output coefficient to its default name.</summary>
public sealed class MacroCodeGenerator_DefaultOutputs
{
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() => new MacroCodeGenerator(DslProject.Load(RepositoryPaths.DslLibrary)));

    [Fact]
    public void Inputs_only_give_every_output_coefficient_its_default_name()
    {
        var outcome = Generator.Value.Generate("SphereCentreAndRadius", [new ClassBindingSpec("omega", "DualSphere3D", "s", 3, 9)], regionLine: 2);
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        Assert.True(outcome.Plan!.DefaultOutputs);
        Assert.Equal(
            ["centre_e1", "centre_e2", "centre_e3", "radius_s", "squaredRadius_s"],
            outcome.Result!.Block.OutputTargets.Values.Order(StringComparer.Ordinal));
        Assert.Equal(["s.e1", "s.e2", "s.e3", "s.ni", "s.no"], outcome.Plan.InputTexts.Values.Order(StringComparer.Ordinal));
    }

    [Fact]
    public void One_bound_output_leaves_the_others_uncomputed()
    {
        var outcome = Generator.Value.Generate("SphereCentreAndRadius",
            [new ClassBindingSpec("omega", "DualSphere3D", "s", 3, 9), new CoefficientBindingSpec("radius", "1", BindingValues.Hole("r"), 4, 9)], regionLine: 2);
        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        Assert.False(outcome.Plan!.DefaultOutputs);
        Assert.Equal(["r"], outcome.Result!.Block.OutputTargets.Values);
    }

    [Fact]
    public void Every_object_class_has_a_class_binding_on_its_frame_that_reads_all_its_coefficients()
    {
        var model = DslProject.Load(RepositoryPaths.DslLibrary).Model;
        (string Class, string Binding)[] expected =
        [
            ("cga5d.NormalizedPoint", "NormalizedPoint3D"), ("cga5d.DualSphere", "DualSphere3D"), ("cga5d.Sphere", "Sphere3D"),
            ("cga5d.DualPlane", "DualPlane3D"), ("cga5d.Plane", "Plane3D"), ("cga5d.Line", "Line3D"), ("cga5d.DualLine", "DualLine3D"),
            ("cga5d.Circle", "Circle3D"), ("cga5d.PointPair", "PointPair3D"), ("cga5d.Versor", "Versor3D"),
            ("e3d.Rotor", "Rotor3D"), ("e3d.UnitRotor", "UnitRotor3D"),
        ];
        foreach (var (className, bindingName) in expected)
        {
            var cls = model.FindClass(className)!;
            var binding = model.ClassBindings[bindingName];
            Assert.Same(cls.Frame, binding.Frame);
            Assert.Equal(cls.VariableBlades.Order(), binding.Coefficients.Select(c => c.Blade.Mask).Order());
        }
    }
}
