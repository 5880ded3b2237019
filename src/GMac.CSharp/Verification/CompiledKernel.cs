namespace GMac.CSharp.Verification;

/// <summary>
/// A generated region compiled as <c>Run(double[] __in, double[] __out)</c>, with the names behind each slot.
/// A float region is compiled over <c>float[]</c> and wrapped: <see cref="IsSingle"/> tells the
/// verifier to round its inputs to float and to expect float accuracy. A vector region computes
/// <see cref="Lanes"/> evaluations at once: slot i of lane l is at <c>i * Lanes + l</c> of each array.
/// </summary>
internal sealed record CompiledKernel(Action<double[], double[]> Run, IReadOnlyList<string> Inputs, IReadOnlyList<string> Outputs)
{
    public bool IsSingle { get; init; }

    public int Lanes { get; init; } = 1;
}
