using RayTracer.Geometry.Meshes;

namespace RayTracer.Cli.Experiments;

/// <summary>One scene rendered with one ray–triangle test: what Table 7-3 lists, and the extra timings.</summary>
public sealed record TrianglesMeasurement
{
    public required string Scene { get; init; }
    public required TriangleTest Test { get; init; }
    public required int Triangles { get; init; }

    /// <summary>Rays the render traced (primary, secondary and shadow).</summary>
    public required long Rays { get; init; }

    /// <summary>Calls of the triangle test during one render, summed over threads.</summary>
    public required long TestInvocations { get; init; }

    /// <summary>Best wall time of the whole render over the repeats (everything but the test is the same).</summary>
    public required TimeSpan RenderTime { get; init; }

    /// <summary>Best CPU time of the process over the same renders: less sensitive than wall time to other jobs on the machine.</summary>
    public required TimeSpan RenderCpuTime { get; init; }

    /// <summary>Best wall time of nearest-hit queries alone (BIH traversal and tests) for a fixed set of rays.</summary>
    public required TimeSpan NearestHitTime { get; init; }

    public required TimeSpan NearestHitCpuTime { get; init; }

    public required int NearestHitRays { get; init; }

    /// <summary>Heap kept alive by the triangle objects, their packed test data and the BIH, measured after a full collection.</summary>
    public required long RetainedBytes { get; init; }

    /// <summary>Largest difference of any colour channel from the Möller–Trumbore image (linear radiance), and how many pixels differ at all.</summary>
    public required double MaxPixelDifference { get; init; }

    public required int DifferingPixels { get; init; }

    public double BytesPerTriangle => (double)RetainedBytes / Triangles;
}
