namespace GMac.Benchmarks.Applications;

/// <summary>Nanoseconds per item of each variant of one kernel.</summary>
public sealed record KernelTiming(string Kernel, double GeneratedNs, double DirectNs, double HandNs)
{
    public double GeneratedOverHand => GeneratedNs / HandNs;

    public double DirectOverGenerated => DirectNs / GeneratedNs;
}
