namespace Twister.Tessellation;

/// <summary>
/// Measures how far a piece of the parameter grid is from flat: an edge (probed as a curve against its
/// chord) or a cell's interior (against the flat triangles it could be cut into). Each edge and each
/// cell draws its random probes from a generator keyed by its grid coordinates, so an edge gets the
/// same measure from both faces beside it and from either side of a seam, whatever order the faces
/// come in; edge measures are kept, so an edge shared by two faces is probed once.
/// </summary>
internal sealed class FlatnessProbe(SurfaceSampler sampler, TessellationOptions options, Seams seams, long resolution)
{
    private const long CellSalt = -1;

    private readonly double _limit = Acceptance.Fraction * options.Tolerance;
    private readonly Dictionary<(long, long, long, long), double> _edges = [];

    /// <summary>The largest gap an edge may show and still be flat: a fraction of the tolerance (see <see cref="Acceptance"/>).</summary>
    public double Limit => _limit;

    /// <summary>
    /// The largest gap probed between the edge from grid point (i0, j0) to (i1, j1), along u or along v,
    /// and its chord from <paramref name="a"/> to <paramref name="b"/>.
    /// </summary>
    public double EdgeError(long i0, long j0, long i1, long j1, TwistablePoint a, TwistablePoint b)
    {
        var m = resolution;
        if (j0 == j1 && ((seams.PoleV0 && j0 == 0) || (seams.PoleV1 && j0 == m)))
        {
            return 0; // the whole edge is one point
        }

        if (i0 == i1 && ((seams.PoleU0 && i0 == 0) || (seams.PoleU1 && i0 == m)))
        {
            return 0;
        }

        // An edge on the far side of a seam is the same curve as its twin on the near side.
        if (i0 == i1 && seams.ClosedU && i0 == m)
        {
            i0 = i1 = 0;
        }

        if (j0 == j1 && seams.ClosedV && j0 == m)
        {
            j0 = j1 = 0;
        }

        var key = (i0, j0, i1, j1);
        if (_edges.TryGetValue(key, out var error))
        {
            return error;
        }

        error = ProbeEdge(Parameter(i0, j0), Parameter(i1, j1), a, b, ProbeRandom.Keyed(options.Seed, i0, j0, i1, j1));
        _edges[key] = error;
        return error;
    }

    /// <summary>
    /// The largest gap probed between the cell's interior and either way of cutting it along a
    /// diagonal: a leaf is cut from its boundary alone, and every triangle with its corners on the
    /// rectangle lies inside the rectangle, so its gap is bounded as the diagonal triangles' are.
    /// </summary>
    public double InteriorError(long i, long j, long du, long dv, ReadOnlySpan<TwistablePoint> corners)
    {
        var random = ProbeRandom.Keyed(options.Seed, i, j, du, dv ^ CellSalt);
        ReadOnlySpan<SurfaceParameter> at = [Parameter(i, j), Parameter(i + du, j), Parameter(i + du, j + dv), Parameter(i, j + dv)];
        ReadOnlySpan<(int, int, int)> triangles = [(0, 1, 2), (0, 2, 3), (0, 1, 3), (1, 2, 3)];
        var worst = 0.0;
        foreach (var (a, b, c) in triangles)
        {
            if (Geometry3.Distance(corners[a], corners[b]) == 0 || Geometry3.Distance(corners[b], corners[c]) == 0 || Geometry3.Distance(corners[c], corners[a]) == 0)
            {
                continue; // two corners on a pole: the mesh drops this triangle, and its region is the other one's
            }

            worst = Math.Max(worst, ProbeTriangle(at[a], at[b], at[c], corners[a], corners[b], corners[c], random));
        }

        return worst;
    }

    private double ProbeEdge(SurfaceParameter pa, SurfaceParameter pb, TwistablePoint a, TwistablePoint b, ProbeRandom random)
    {
        var n = options.ProbeCount;
        var worst = 0.0;
        for (var k = -1; k < n; k++)
        {
            // The middle first, where a curve that bends one way strays most, then one random point per stratum.
            var s = k < 0 ? 0.5 : (k + random.NextDouble()) / n;
            var q = sampler.Point(pa.U + s * (pb.U - pa.U), pa.V + s * (pb.V - pa.V));
            worst = Math.Max(worst, Geometry3.Distance(q, Geometry3.Lerp(a, b, s)));
        }

        return worst;
    }

    private double ProbeTriangle(SurfaceParameter pa, SurfaceParameter pb, SurfaceParameter pc, TwistablePoint qa, TwistablePoint qb, TwistablePoint qc, ProbeRandom random)
    {
        var worst = 0.0;
        for (var k = -3; k <= options.ProbeCount; k++)
        {
            // The middles of the sides first, where a surface curved the same way in u and v strays most
            // (the diagonal's middle gets both bends), then the centroid, where a bump between flat
            // edges shows most, then random points.
            var (beta, gamma) = k switch { -3 => (0.5, 0.0), -2 => (0.0, 0.5), -1 => (0.5, 0.5), _ => (1.0 / 3, 1.0 / 3) };
            if (k > 0)
            {
                beta = random.NextDouble();
                gamma = random.NextDouble();
                if (beta + gamma > 1)
                {
                    (beta, gamma) = (1 - beta, 1 - gamma);
                }
            }

            var alpha = 1 - beta - gamma;
            var q = sampler.Point(alpha * pa.U + beta * pb.U + gamma * pc.U, alpha * pa.V + beta * pb.V + gamma * pc.V);
            worst = Math.Max(worst, Geometry3.Distance(q, Geometry3.Barycentric(qa, qb, qc, beta, gamma)));
        }

        return worst;
    }

    public SurfaceParameter Parameter(long i, long j) => new((double)i / resolution, (double)j / resolution);
}
