namespace GMac.CSharp.Verification;

/// <summary>How one region fared: samples compared, the largest relative error, and the first failure if any.</summary>
internal sealed record VerificationResult(int Samples, double MaxRelativeError, double Tolerance, string? Failure)
{
    public bool Passed => Failure is null && Samples > 0;
}
