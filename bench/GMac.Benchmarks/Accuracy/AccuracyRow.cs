namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// The errors of one kernel on one input family: per item the normwise relative error
/// (see <see cref="AccuracyHarness.ItemError"/>), summarised over the batch.
/// </summary>
public sealed record AccuracyRow(string Kernel, InputFamily Family, int Items, double GeneratedMedian, double GeneratedMax, double HandMedian, double HandMax)
{
    /// <summary>Errors below two units of double's epsilon (2⁻⁵²) count as that much when comparing, so exact results do not divide by zero.</summary>
    public const double Floor = 2 * 2.220446049250313e-16;

    /// <summary>How far the generated code's worst error is above the hand code's, both floored.</summary>
    public double Ratio => Math.Max(GeneratedMax, Floor) / Math.Max(HandMax, Floor);

    /// <summary>The goal: generated error within 10× of hand.</summary>
    public bool Met => Ratio <= 10;
}
