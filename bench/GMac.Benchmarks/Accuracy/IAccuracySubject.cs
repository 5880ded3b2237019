namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// What the accuracy harness needs of a kernel beyond timing: its inputs and outputs as boxed
/// structs, so that one harness serves every kernel whatever its value types.
/// </summary>
public interface IAccuracySubject
{
    /// <summary>Name of the first parameter of the kernel's <c>Generated</c> method, which binding texts start with.</summary>
    string InputParameter { get; }

    object RandomInput(Random random);

    /// <summary>Replaces the batch by these inputs (boxed values of the kernel's input type).</summary>
    void SetInputs(IReadOnlyList<object> inputs);

    object Input(int index);

    /// <summary>A zero value of the kernel's output type, boxed, for writing a reference into.</summary>
    object EmptyOutput();

    /// <summary>The components of a boxed output in the order <see cref="Kernels.IGaKernel.Output"/> lists them.</summary>
    IReadOnlyList<double> ComponentsOf(object output);
}
