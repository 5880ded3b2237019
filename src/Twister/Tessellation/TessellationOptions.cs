namespace Twister.Tessellation;

/// <summary>
/// How finely to sample a curve or a surface. <see cref="Tolerance"/> is an absolute distance in the
/// units of the shape: the largest allowed gap between the shape and its polyline or triangle mesh,
/// measured from a point of the shape to the point of the chord or flat triangle at the same
/// parameters (which bounds the distance to the chord or triangle).
/// </summary>
public sealed record TessellationOptions(double Tolerance)
{
    /// <summary>Default for <see cref="MaxTriangles"/> and <see cref="MaxSegments"/>.</summary>
    public const int DefaultBudget = 2_000_000;

    /// <summary>Seed of the random probes; the same seed gives the same tessellation.</summary>
    public int Seed { get; init; } = 1;

    /// <summary>Random probes per curve segment (one in each of as many equal strata) and per face (plus its centroid).</summary>
    public int ProbeCount { get; init; } = 4;

    /// <summary>
    /// Cells of the starting grid along each parameter (curves start with this many equal segments).
    /// A closed direction needs at least three so no starting face is degenerate.
    /// </summary>
    public int InitialCells { get; init; } = 4;

    /// <summary>The most triangles a surface may produce; more throws before the memory is spent.</summary>
    public int MaxTriangles { get; init; } = DefaultBudget;

    /// <summary>The most segments a curve may produce.</summary>
    public int MaxSegments { get; init; } = DefaultBudget;

    internal void Validate()
    {
        if (!(Tolerance > 0) || double.IsInfinity(Tolerance))
        {
            throw new ArgumentOutOfRangeException(nameof(Tolerance), Tolerance, $"The tessellation tolerance must be a positive finite distance; got {Tolerance}.");
        }

        if (ProbeCount < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(ProbeCount), ProbeCount, "At least one probe per segment or face is needed.");
        }

        if (InitialCells < 3)
        {
            throw new ArgumentOutOfRangeException(nameof(InitialCells), InitialCells, "The starting grid needs at least three cells along each parameter.");
        }

        if (MaxTriangles < 1 || MaxSegments < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(MaxTriangles), "The triangle and segment budgets must be positive.");
        }
    }
}
