using GMac.Core.Algebra;
using GMac.Dsl.Compilation;
using GMac.Dsl.Generation;
using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// A class binding may map a blade coefficient to minus its member (UnitRotor3D reads e3^e1, so
/// the e1^e3 coefficient is −zx): the unit norm of a normalized class must pay off the same
/// whatever the signs, so the library's class bindings cost what unsigned coefficient bindings do.
/// </summary>
public sealed class MacroCodeGenerator_NormalizedClassBindings
{
    private static readonly Lazy<DslProject> Project = new(() => DslProject.Load(RepositoryPaths.DslLibrary));
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() => new MacroCodeGenerator(Project.Value));

    /// <summary>Every library macro input of a normalized class with every class binding that binds all of that class's coefficients.</summary>
    public static TheoryData<string, string, string> NormalizedInputsAndBindings()
    {
        var data = new TheoryData<string, string, string>();
        var model = Project.Value.Model;
        foreach (var binding in model.ClassBindings.Values.OrderBy(b => b.Name, StringComparer.Ordinal))
        foreach (var macro in model.Macros.Values.OrderBy(m => m.Name, StringComparer.Ordinal))
        foreach (var input in macro.Inputs.Where(i => i.Class is { IsNormalized: true } c && c.Frame == binding.Frame))
        {
            var bound = binding.Coefficients.Select(c => c.Blade.Mask).ToHashSet();
            if (input.Class!.VariableBlades.All(bound.Contains)) data.Add(binding.Name, macro.Name, input.Name);
        }
        return data;
    }

    [Fact]
    public void The_library_binds_some_normalized_input_through_a_class_binding_with_a_sign()
    {
        // Otherwise the theory below would test nothing that could go wrong.
        var model = Project.Value.Model;
        Assert.Contains(NormalizedInputsAndBindings(), row => model.ClassBindings[(string)row[0]].Coefficients.Any(c => c.Blade.Sign < 0));
    }

    [Theory]
    [MemberData(nameof(NormalizedInputsAndBindings))]
    public void Class_binding_costs_what_unsigned_coefficient_bindings_cost(string bindingName, string macroName, string inputName)
    {
        var model = Project.Value.Model;
        var binding = model.ClassBindings[bindingName];
        var macro = model.Macros[macroName];
        var input = macro.Inputs.Single(i => i.Name == inputName);
        var frame = new CoreFrames()[binding.Frame];
        // The same members in the same order, so that only the signs differ.
        var unsigned = binding.Coefficients
            .Where(c => input.Class!.VariableBlades.Contains(c.Blade.Mask))
            .Select(c => (BindingSpec)new CoefficientBindingSpec(inputName, frame.BladeName(new BasisBlade(c.Blade.Mask)),
                BindingValues.Hole($"R.{((BoundMemberReference)c.Value).Path}"), 1, 1))
            .ToList();
        var others = Others(macroName, inputName);

        var withClass = Generator.Value.Generate(macroName, [new ClassBindingSpec(inputName, bindingName, "R", 1, 1), .. others]);
        var withCoefficients = Generator.Value.Generate(macroName, [.. unsigned, .. others]);

        Assert.True(withClass.Succeeded, string.Join("; ", withClass.Errors));
        Assert.True(withCoefficients.Succeeded, string.Join("; ", withCoefficients.Errors));
        var (a, b) = (withClass.Result!.Statistics, withCoefficients.Result!.Statistics);
        Assert.True((a.Additions, a.Multiplications, a.Divisions, a.Calls) == (b.Additions, b.Multiplications, b.Divisions, b.Calls),
            $"{macroName} with {inputName} through {bindingName}: {a}; through unsigned coefficients: {b}");
    }

    [Fact]
    public void ApplyUnitRotor3D_through_the_library_class_binding_is_12_additions_and_18_multiplications_and_rotates()
    {
        var outcome = Generator.Value.Generate("ApplyUnitRotor3D",
            [new ClassBindingSpec("r", "UnitRotor3D", "R", 1, 1), new ClassBindingSpec("x", "Point3D", "p", 1, 1), new ClassBindingSpec("y", "Point3D", "q", 1, 1)]);

        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var s = outcome.Result!.Statistics;
        Assert.True((s.Additions, s.Multiplications, s.Divisions, s.Calls) == (12, 18, 0, 0), $"{s}\n{outcome.Result.Block}");
        // The reduced form holds only for unit rotors: compare it with the macro on doubles there.
        var random = new Random(5);
        var texts = outcome.Plan!.InputTexts;
        string Name(string text) => texts.Single(kv => kv.Value == text).Key;
        for (var sample = 0; sample < 20; sample++)
        {
            double[] r = [.. Enumerable.Range(0, 4).Select(_ => 2 * random.NextDouble() - 1)];
            var norm = Math.Sqrt(r.Sum(c => c * c));
            var values = new Dictionary<string, double>(StringComparer.Ordinal)
            {
                [Name("R.s")] = r[0] / norm, [Name("R.xy")] = r[1] / norm, [Name("R.yz")] = r[2] / norm, [Name("R.zx")] = r[3] / norm,
                [Name("p.x")] = 10 * random.NextDouble() - 5, [Name("p.y")] = 10 * random.NextDouble() - 5, [Name("p.z")] = 10 * random.NextDouble() - 5,
            };
            var actual = outcome.Result.Block.Evaluate(values);
            var expected = outcome.Plan.NumericReference(values);
            Assert.Equal(3, expected.Count);
            foreach (var (key, value) in expected) Assert.Equal(value, actual[key], 12);
        }
    }

    /// <summary>The default bindings of every other input (outputs get default names).</summary>
    private static List<BindingSpec> Others(string macroName, string inputName)
    {
        var macro = Project.Value.Model.Macros[macroName];
        var inputs = macro.Inputs.Select(i => i.Name).ToHashSet(StringComparer.Ordinal);
        return [.. Generator.Value.DefaultBindings(macroName).OfType<CoefficientBindingSpec>().Where(c => c.Parameter != inputName && inputs.Contains(c.Parameter))];
    }
}
