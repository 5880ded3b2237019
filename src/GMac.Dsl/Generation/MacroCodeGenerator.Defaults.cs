using GMac.Core.Algebra;

namespace GMac.Dsl.Generation;

public sealed partial class MacroCodeGenerator
{
    /// <summary>
    /// Bindings that read every variable input coefficient from a target-language name such as
    /// <c>u_e1</c> and write every output coefficient to one such as <c>w_e1_e2</c>: what
    /// <c>gmac show</c> uses when no binding is given, and what benchmarks of generation use.
    /// </summary>
    public IReadOnlyList<BindingSpec> DefaultBindings(string macroName) =>
        _project.Model.Macros.TryGetValue(macroName, out var macro) ? [.. DefaultBindings(macro, inputs: true), .. DefaultBindings(macro, inputs: false)] : [];

    /// <summary>The default bindings of the macro's inputs, or of its outputs (every coefficient of their classes).</summary>
    private List<BindingSpec> DefaultBindings(Semantics.MacroSymbol macro, bool inputs)
    {
        var bindings = new List<BindingSpec>();
        foreach (var parameter in inputs ? macro.Inputs : macro.Outputs)
        {
            var frame = _frames[parameter.Class!.Frame];
            var blades = parameter.Kind == Semantics.VariableKind.Input ? parameter.Class.VariableBlades : parameter.Class.AllBlades;
            foreach (var id in blades.Order())
            {
                var blade = frame.BladeName(new BasisBlade(id));
                var name = id == 0 ? $"{parameter.Name}_s" : $"{parameter.Name}_{blade.Replace('^', '_')}";
                bindings.Add(new CoefficientBindingSpec(parameter.Name, blade, new HostExpression(name, HasEffects: false), 1, 1));
            }
        }
        return bindings;
    }

    /// <summary>Names of all macros of the project, in a stable order.</summary>
    public IEnumerable<string> MacroNames => _project.Model.Macros.Keys.Order(StringComparer.Ordinal);
}
