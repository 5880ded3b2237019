namespace GMac.Cli.Verification;

/// <summary>A generated region compiled as <c>Run(double[] __in, double[] __out)</c>, with the names behind each slot.</summary>
internal sealed record CompiledKernel(Action<double[], double[]> Run, IReadOnlyList<string> Inputs, IReadOnlyList<string> Outputs);
