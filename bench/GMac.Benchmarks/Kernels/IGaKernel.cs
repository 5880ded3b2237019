namespace GMac.Benchmarks.Kernels;

/// <summary>One GA application of thesis §7.1 with its three implementations over a batch of inputs.</summary>
public interface IGaKernel
{
    /// <summary>The macro of the <c>dsl/</c> library the generated variant binds.</summary>
    string MacroName { get; }

    /// <summary>Where the formula comes from, for the report.</summary>
    string Source { get; }

    /// <summary>Operations of the hand variant per item, counted by hand from its source.</summary>
    OperationCount HandOperations { get; }

    int Count { get; }

    /// <summary>Fills the batch with random inputs fixed by <paramref name="seed"/>.</summary>
    void Setup(int count, int seed);

    /// <summary>Runs one variant over the whole batch and keeps its outputs for <see cref="Output"/>.</summary>
    void Run(Variant variant);

    /// <summary>
    /// Runs one variant over the whole batch for timing: every variant writes into the same output
    /// array, so all of them touch the same memory. <see cref="Output"/> does not see these runs.
    /// </summary>
    void Time(Variant variant);

    /// <summary>The doubles of input <paramref name="index"/>, in the order its struct declares them (nested structs in place).</summary>
    IReadOnlyList<double> InputDoubles(int index);

    /// <summary>The output coefficients one variant wrote for item <paramref name="index"/> in its last run.</summary>
    IReadOnlyList<double> Output(Variant variant, int index);
}
