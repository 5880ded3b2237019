namespace RayTracer.Viewing;

/// <summary>Settings of one render that do not belong to the scene.</summary>
public sealed class RenderOptions
{
    /// <summary>Seed of all per-pixel random streams; the image is a function of it alone.</summary>
    public ulong Seed { get; init; }

    /// <summary>Worker threads; 0 uses every core.</summary>
    public int Threads { get; init; }

    /// <summary>Side of a square tile in pixels.</summary>
    public int TileSize { get; init; } = 16;

    /// <summary>Called after each finished tile with (tiles done, tile count); may be called from any thread.</summary>
    public Action<int, int>? Progress { get; init; }

    public CancellationToken Cancellation { get; init; }
}
