using System.Reflection;
using GMac.Benchmarks.Accuracy;

namespace GMac.Benchmarks.Kernels;

// The boxed view of a kernel that the accuracy harness works through.
public abstract partial class GaKernel<TIn, TOut> : IAccuracySubject
{
    public string InputParameter =>
        GetType().GetMethod("Generated", BindingFlags.Public | BindingFlags.Static)?.GetParameters().FirstOrDefault()?.Name
        ?? throw new InvalidOperationException($"{GetType().Name} has no public static Generated method");

    public object RandomInput(Random random) => CreateInput(random);

    public void SetInputs(IReadOnlyList<object> inputs)
    {
        ArgumentOutOfRangeException.ThrowIfZero(inputs.Count);
        _inputs = inputs.Select(i => (TIn)i).ToArray();
        AllocateOutputs();
    }

    public object Input(int index) => _inputs[index];

    public object EmptyOutput() => default(TOut);

    public IReadOnlyList<double> ComponentsOf(object output) => Components((TOut)output);
}
