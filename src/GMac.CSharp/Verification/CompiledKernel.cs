namespace GMac.CSharp.Verification;

/// <summary>
/// A generated region compiled as <c>Run(double[] __in, double[] __out)</c>, with the names behind each slot.
/// A float region is compiled over <c>float[]</c> and wrapped: <see cref="IsSingle"/> tells the
/// verifier to round its inputs to float and to expect float accuracy.
/// </summary>
internal sealed record CompiledKernel(Action<double[], double[]> Run, IReadOnlyList<string> Inputs, IReadOnlyList<string> Outputs)
{
    public bool IsSingle { get; init; }
}
