namespace RayTracer.Cli.Experiments;

/// <summary>How the ray–triangle experiment runs: mesh detail, image size, threads and repeats.</summary>
public sealed record TrianglesSettings
{
    /// <summary>Fraction of the thesis's triangle counts (1 = Table 7-3's counts).</summary>
    public double Detail { get; init; } = 1;

    public int Width { get; init; } = 320;
    public int Height { get; init; } = 240;
    public int Threads { get; init; } = 1;

    /// <summary>Timed renders per scene and test; the best is kept.</summary>
    public int Repeats { get; init; } = 3;

    /// <summary>Rays of the nearest-hit timing, from the eye towards random points of the mesh's bounds.</summary>
    public int NearestHitRays { get; init; } = 200_000;

    /// <summary>Names of the scenes to run; empty runs all five.</summary>
    public IReadOnlyList<string> Scenes { get; init; } = [];

    /// <summary>Small meshes and images and one repeat: for checking the code paths, not for figures.</summary>
    public static TrianglesSettings Quick { get; } = new() { Detail = 0.02, Width = 64, Height = 48, Repeats = 1, NearestHitRays = 2_000 };
}
