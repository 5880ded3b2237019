namespace GMac.Benchmarks.Kernels;

/// <summary>
/// Batch plumbing shared by the kernels. Each kernel loops over the batch itself so that its
/// per-item methods can be inlined: one virtual call per batch, none per item. Timed runs of all
/// variants read the same input array and write the same output array, so no variant gains or
/// loses by where its arrays happen to lie (cache sets, loads that alias earlier stores modulo 4 KiB).
/// </summary>
public abstract partial class GaKernel<TIn, TOut> : IGaKernel where TIn : struct where TOut : struct
{
    private TIn[] _inputs = [];
    private readonly Dictionary<Variant, TOut[]> _outputs = [];
    private TOut[] _timed = [];

    public abstract string MacroName { get; }
    public abstract string Source { get; }
    public abstract OperationCount HandOperations { get; }
    public int Count => _inputs.Length;

    public void Setup(int count, int seed)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(count);
        var random = new Random(seed);
        _inputs = new TIn[count];
        for (var i = 0; i < count; i++) _inputs[i] = CreateInput(random);
        AllocateOutputs();
    }

    public void Run(Variant variant) => Run(variant, _outputs[variant]);

    public void Time(Variant variant) => Run(variant, _timed);

    private void AllocateOutputs()
    {
        foreach (var v in Enum.GetValues<Variant>()) _outputs[v] = new TOut[_inputs.Length];
        _timed = new TOut[_inputs.Length];
    }

    private void Run(Variant variant, TOut[] outputs)
    {
        switch (variant)
        {
            case Variant.Generated: RunGenerated(_inputs, outputs); break;
            case Variant.Direct: RunDirect(_inputs, outputs); break;
            case Variant.Hand: RunHand(_inputs, outputs); break;
            default: throw new ArgumentOutOfRangeException(nameof(variant));
        }
    }

    public IReadOnlyList<double> Output(Variant variant, int index) => Components(_outputs[variant][index]);

    public IReadOnlyList<double> InputDoubles(int index) => StructFields.Doubles(_inputs[index]);

    protected abstract TIn CreateInput(Random random);

    protected abstract double[] Components(TOut value);

    protected abstract void RunGenerated(TIn[] inputs, TOut[] outputs);

    protected abstract void RunDirect(TIn[] inputs, TOut[] outputs);

    protected abstract void RunHand(TIn[] inputs, TOut[] outputs);

    /// <summary>Uniform in [−1, 1).</summary>
    protected static double Signed(Random random) => random.NextDouble() * 2 - 1;
}
