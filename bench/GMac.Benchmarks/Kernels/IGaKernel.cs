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

    /// <summary>Runs one variant over the whole batch.</summary>
    void Run(Variant variant);

    /// <summary>The output coefficients one variant wrote for item <paramref name="index"/> in its last run.</summary>
    IReadOnlyList<double> Output(Variant variant, int index);
}
