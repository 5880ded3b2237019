namespace Twister.Tessellation;

/// <summary>
/// Which sides of the parameter square meet (a closed direction) or collapse to one point (a pole),
/// found by <see cref="SeamDetector"/>. Grid vertices on such sides are copies of one canonical vertex.
/// </summary>
internal sealed class Seams(int cells)
{
    public bool ClosedU { get; init; }

    public bool ClosedV { get; init; }

    public bool PoleU0 { get; init; }

    public bool PoleU1 { get; init; }

    public bool PoleV0 { get; init; }

    public bool PoleV1 { get; init; }

    /// <summary>Largest raw normal length found on the grid, the yardstick for a vanishing normal.</summary>
    public double NormalScale { get; init; }

    /// <summary>
    /// Parameters around a pole side at which to average the nearby normals: the cell midpoints, evenly
    /// spread and none counted twice where the side closes on itself, so the tilts cancel.
    /// </summary>
    public IReadOnlyList<SurfaceParameter> AroundPole(bool alongU, double fixedValue) =>
        [.. Enumerable.Range(0, cells).Select(k => (k + 0.5) / cells)
            .Select(t => alongU ? new SurfaceParameter(t, fixedValue) : new SurfaceParameter(fixedValue, t))];
}
