using GMac.CSharp.Emit;
using GMac.CSharp.Verification;
using GMac.Dsl.Generation;

namespace GMac.CSharp.Tests.Support;

/// <summary>
/// A library macro generated with its default bindings (<c>u_e1</c> in, <c>w_e1</c> out) and compiled
/// in memory as double or float code, callable by those names.
/// </summary>
internal sealed class MacroKernel
{
    private readonly CompiledKernel _kernel;
    private readonly Dictionary<string, string> _outputNames;

    private MacroKernel(CompiledKernel kernel, BindingPointPlan plan, string code, Dictionary<string, string> outputNames)
    {
        _kernel = kernel;
        Plan = plan;
        Code = code;
        _outputNames = outputNames;
        InputNames = kernel.Inputs.Select(i => plan.InputTexts[i]).ToList();
    }

    public BindingPointPlan Plan { get; }

    /// <summary>The kernel as it is compiled, with array slots for inputs and outputs.</summary>
    public string Code { get; }

    /// <summary>Default names of the inputs, in slot order.</summary>
    public IReadOnlyList<string> InputNames { get; }

    public CompiledKernel Kernel => _kernel;

    public static MacroKernel Create(string macro, string scalarType) => Create(macro, scalarType, SharedDsl.Context);

    /// <summary>A macro of another DSL project (the library plus test files).</summary>
    public static MacroKernel Create(string macro, string scalarType, GMac.CSharp.BindingPoints.GenerationContext context)
    {
        var bindings = context.Generator.DefaultBindings(macro);
        var outcome = context.Generator.Generate(macro, bindings, 1);
        Assert.True(outcome.Succeeded, string.Join("\n", outcome.Errors));
        var remapped = KernelCompiler.Remap(outcome.Result!.Block, outcome.Plan!.InputTexts.Keys);
        var (kernel, error) = KernelCompiler.Compile([remapped], [scalarType])[0];
        Assert.True(kernel is not null, error);
        var code = GMac.CSharp.Emit.CSharpEmitter.Emit(outcome.Result.Block, new GMac.CSharp.Emit.CSharpEmitOptions { ScalarType = scalarType });
        // Output keys ("w.e1") to the default names ("w_e1") the bindings gave them.
        var outputNames = bindings.OfType<CoefficientBindingSpec>()
            .Where(b => outcome.Result.Block.OutputTargets.ContainsKey($"{b.Parameter}.{b.Blade}"))
            .ToDictionary(b => $"{b.Parameter}.{b.Blade}", b => b.Value.Text, StringComparer.Ordinal);
        return new MacroKernel(kernel!, outcome.Plan, code, outputNames);
    }

    /// <summary>Runs the kernel; inputs not given are zero. The result is keyed by default output names.</summary>
    public Dictionary<string, double> Run(IReadOnlyDictionary<string, double> inputs)
    {
        foreach (var name in inputs.Keys) Assert.Contains(name, InputNames);
        var input = InputNames.Select(n => inputs.TryGetValue(n, out var v) ? v : 0.0).ToArray();
        var output = new double[_kernel.Outputs.Count];
        _kernel.Run(input, output);
        return _kernel.Outputs.Select((key, j) => (Name: _outputNames[key], Value: output[j])).ToDictionary(x => x.Name, x => x.Value, StringComparer.Ordinal);
    }
}
