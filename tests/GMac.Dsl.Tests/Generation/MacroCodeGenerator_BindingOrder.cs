using GMac.Core.Algebra;
using GMac.Dsl.Compilation;
using GMac.Dsl.Generation;
using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// The unit norm of a normalized input is one relation whatever the binding point looks like: the
/// order of its lines (which names the inputs in another order), a sign on a coefficient or a
/// constant scale must not change what the generated code costs. Each library class binding of a
/// normalized class is bound first and last, and as coefficients with signs and a scale.
/// </summary>
public sealed class MacroCodeGenerator_BindingOrder
{
    private static readonly Lazy<DslProject> Project = new(() => DslProject.Load(RepositoryPaths.DslLibrary));
    private static readonly Lazy<MacroCodeGenerator> Generator = new(() => new MacroCodeGenerator(Project.Value));

    public static TheoryData<string, string, string> NormalizedInputsAndBindings() => MacroCodeGenerator_NormalizedClassBindings.NormalizedInputsAndBindings();

    [Theory]
    [MemberData(nameof(NormalizedInputsAndBindings))]
    public void Cost_does_not_depend_on_the_order_or_the_signs_of_the_binding_lines(string bindingName, string macroName, string inputName)
    {
        var model = Project.Value.Model;
        var binding = model.ClassBindings[bindingName];
        var input = model.Macros[macroName].Inputs.Single(i => i.Name == inputName);
        var frame = new CoreFrames()[binding.Frame];
        var coefficients = binding.Coefficients.Where(c => input.Class!.VariableBlades.Contains(c.Blade.Mask)).ToList();
        List<BindingSpec> Coefficients(Func<int, string> factor) =>
        [
            .. coefficients.Select((c, i) => (BindingSpec)new CoefficientBindingSpec(inputName, frame.BladeName(new BasisBlade(c.Blade.Mask)),
                BindingValues.ScaledHole(factor(i), $"R.{((BoundMemberReference)c.Value).Path}"), 1, 1)),
        ];
        var others = Others(macroName, inputName);
        var classLine = new ClassBindingSpec(inputName, bindingName, "R", 1, 1);
        var variants = new (string Name, List<BindingSpec> Lines)[]
        {
            ("class binding first", [classLine, .. others]),
            ("class binding last", [.. others, classLine]),
            ("every other coefficient negated, first", [.. Coefficients(i => i % 2 == 1 ? "-" : ""), .. others]),
        };
        var counts = variants.Select(v =>
        {
            var outcome = Generator.Value.Generate(macroName, v.Lines);
            Assert.True(outcome.Succeeded, $"{v.Name}: {string.Join("; ", outcome.Errors)}");
            var s = outcome.Result!.Statistics;
            return (v.Name, Counts: (s.Additions, s.Multiplications, s.Divisions, s.Calls));
        }).ToList();
        Assert.True(counts.Select(c => c.Counts).Distinct().Count() == 1,
            $"{macroName} with {inputName} through {bindingName}: " + string.Join("; ", counts.Select(c => $"{c.Name} {c.Counts}")));
    }

    /// <summary>The default bindings of every other input (outputs get default names).</summary>
    private static List<BindingSpec> Others(string macroName, string inputName)
    {
        var macro = Project.Value.Model.Macros[macroName];
        var inputs = macro.Inputs.Select(i => i.Name).ToHashSet(StringComparer.Ordinal);
        return [.. Generator.Value.DefaultBindings(macroName).OfType<CoefficientBindingSpec>().Where(c => c.Parameter != inputName && inputs.Contains(c.Parameter))];
    }
}
