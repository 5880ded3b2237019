using GMac.Benchmarks.Generation;
using GMac.Benchmarks.Kernels;
using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Accuracy;
using GMac.Core.Numerics;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// The exact outputs of a kernel for any input: its binding point regenerated from the library and
/// run by <see cref="ExactEvaluator"/> with <see cref="HighPrecision"/> functions, inputs read from and outputs written into the
/// kernel's own structs through the binding texts. Nothing here is specific to one kernel.
/// </summary>
public sealed class KernelReference
{
    private readonly IAccuracySubject _subject;
    private readonly CodeBlock _block;
    private readonly (string Variable, string Path)[] _inputs;
    private readonly (string Variable, int Component)[] _outputs;
    private readonly int _components;

    public KernelReference(IGaKernel kernel, MacroCodeGenerator generator)
    {
        _subject = kernel as IAccuracySubject
            ?? throw new InvalidOperationException($"{kernel.MacroName}: the kernel does not expose its inputs and outputs (derive it from GaKernel)");
        var regions = KernelRegions.RegionsOf(kernel.GetType().Name, kernel.MacroName);
        if (regions.Count != 1)
            throw new InvalidOperationException($"{kernel.MacroName}: the accuracy reference needs exactly one binding point, found {regions.Count}");
        var outcome = generator.Generate(kernel.MacroName, regions[0]);
        if (!outcome.Succeeded)
            throw new InvalidOperationException($"{kernel.MacroName}: {string.Join("; ", outcome.Errors.Select(e => $"{e.Code}: {e.Message}"))}");
        _block = outcome.Result!.Block;

        var parameter = _subject.InputParameter;
        _inputs = _block.InputText.Select(kv =>
        {
            var text = kv.Value.Trim();
            if (!StructPath.IsPath(text) || !text.StartsWith(parameter + ".", StringComparison.Ordinal) && text != parameter)
                throw new InvalidOperationException($"{kernel.MacroName}: input '{text}' is not a member of the parameter '{parameter}'");
            return (kv.Key, text);
        }).ToArray();

        // Which component of Output(...) each output target is: write 1 into that target alone.
        var empty = _subject.EmptyOutput();
        _components = _subject.ComponentsOf(empty).Count;
        _outputs = _block.OutputTargets.Select(kv =>
        {
            var probe = StructPath.Write(_subject.EmptyOutput(), kv.Value.Trim(), 1.0);
            var values = _subject.ComponentsOf(probe);
            var hits = Enumerable.Range(0, values.Count).Where(i => values[i] != 0).ToArray();
            if (hits.Length != 1 || values[hits[0]] != 1.0)
                throw new InvalidOperationException($"{kernel.MacroName}: output '{kv.Value}' is not one component of the kernel's output");
            return (kv.Key, hits[0]);
        }).ToArray();
        if (_outputs.Select(o => o.Component).Distinct().Count() != _components)
            throw new InvalidOperationException($"{kernel.MacroName}: the binding point does not write every component of the kernel's output");
    }

    /// <summary>The exact components of item <paramref name="index"/> of the kernel's batch; null where the macro is undefined there.</summary>
    public Rational[]? Evaluate(int index)
    {
        var input = _subject.Input(index);
        var values = _inputs.ToDictionary(i => i.Variable, i => Rational.FromDouble(StructPath.Read(input, i.Path)), StringComparer.Ordinal);
        if (ExactEvaluator.Evaluate(_block, values, HighPrecision.Call) is not { } outputs) return null;
        var result = new Rational[_components];
        foreach (var (variable, component) in _outputs) result[component] = outputs[variable];
        return result;
    }
}
