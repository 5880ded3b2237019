namespace RayTracer.Viewing;

/// <summary>The image of a render with its cost.</summary>
public sealed record RenderResult(FrameBuffer Image, long PrimaryRays, long TotalRays, TimeSpan Elapsed)
{
    /// <summary>Millions of rays (primary, secondary and shadow) per second of wall time.</summary>
    public double MegaRaysPerSecond => Elapsed.TotalSeconds > 0 ? TotalRays / Elapsed.TotalSeconds / 1e6 : 0;
}
