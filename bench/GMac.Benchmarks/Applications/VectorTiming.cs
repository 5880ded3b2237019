namespace GMac.Benchmarks.Applications;

/// <summary>
/// Nanoseconds per item of a kernel's generated scalar code and of its vector forms, with the ratios
/// timed in pairs (<see cref="PairedRatioTimer"/>); a null is a form not timed (no hand code, Vector512 not in hardware).
/// </summary>
public sealed record VectorTiming(string Kernel, double ScalarNs, double Vector256Ns, double ScalarOver256,
    double? Vector512Ns, double? ScalarOver512, double? Hand256Ns, double? GeneratedOverHand256);
