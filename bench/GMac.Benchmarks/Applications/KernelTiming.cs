namespace GMac.Benchmarks.Applications;

/// <summary>Nanoseconds per item of each variant of one kernel.</summary>
public sealed record KernelTiming(string Kernel, double GeneratedNs, double DirectNs, double HandNs)
{
    /// <summary>The ratio timed in pairs (<see cref="PairedRatioTimer"/>), where it was.</summary>
    public double? PairedGeneratedOverHand { get; init; }

    /// <summary>The lowest and highest of the per-process paired ratios whose median is <see cref="PairedGeneratedOverHand"/>, where there were several.</summary>
    public (double Min, double Max)? PairedRange { get; init; }

    /// <summary>Generated over hand: the paired ratio where there is one, else the ratio of the two times.</summary>
    public double GeneratedOverHand => PairedGeneratedOverHand ?? GeneratedNs / HandNs;

    public double DirectOverGenerated => DirectNs / GeneratedNs;
}
