namespace Twister.Tessellation;

/// <summary>
/// A segment or face is accepted when every probe lies within this fraction of the tolerance. The
/// probes are a handful of points, so the gap between them can be larger than what they saw; for a
/// gap that grows like a parabola across a segment, stratified probes see at least three quarters of
/// its peak, so half the tolerance keeps the true gap within the tolerance with room to spare.
/// </summary>
internal static class Acceptance
{
    public const double Fraction = 0.5;

    /// <summary>Deeper bisection than this means the shape does not flatten at all (a kink, a jump or rounding noise).</summary>
    public const int MaxDepth = 48;
}
