namespace Twister.Tessellation;

/// <summary>
/// One run of <see cref="SurfaceTessellator"/>. Faces are rectangles of the parameter grid, cut in u,
/// in v or both as their flatness asks; vertices sit on a fine integer grid, so a sample made by one
/// face is found exactly by every face whose side passes through it.
/// </summary>
internal sealed class SurfaceTessellation
{
    /// <summary>
    /// Grid steps across a starting cell: 2^20 · 3^6 · 5^2 · 7^2, so a cell can be cut into 2 to 8 equal
    /// parts many times over and every vertex still sits exactly on the grid.
    /// </summary>
    private const long CellSteps = (1L << 20) * 729 * 25 * 49;

    /// <summary>The most parts a cell is cut into at once along one direction.</summary>
    private const int MaxParts = 8;

    /// <summary>
    /// When the iso-curves of a cell stray less than this share of its interior gap, the gap comes from
    /// a twist (as in z = uv), which shrinks only in proportion to a side's length.
    /// </summary>
    private const double TwistShare = 0.25;

    private readonly SurfaceSampler _sampler;
    private readonly TessellationOptions _options;
    private readonly MeshBuilder _mesh;
    private readonly long _resolution;
    private readonly Dictionary<(long I, long J), int> _vertices = [];
    private readonly GridLines _lines = new();
    private readonly List<(long I, long J, long Du, long Dv)> _leaves = [];
    private Seams _seams = new(1);
    private FlatnessProbe _probe = null!;

    public SurfaceTessellation(IParametricSurface surface, TessellationOptions options)
    {
        _sampler = new SurfaceSampler(surface);
        _options = options;
        _mesh = new MeshBuilder(options);
        _resolution = options.InitialCells * CellSteps;
    }

    public TriangleMesh Run()
    {
        _seams = SeamDetector.Detect(_sampler, _options.InitialCells, new ProbeRandom(_options.Seed));
        _sampler.NormalScale = _seams.NormalScale;
        _probe = new FlatnessProbe(_sampler, _options, _seams, _resolution);
        var size = CellSteps;
        for (var i = 0; i < _options.InitialCells; i++)
        {
            for (var j = 0; j < _options.InitialCells; j++)
            {
                Refine(i * size, j * size, size, size);
            }
        }

        _lines.Freeze();
        var boundary = new List<BoundaryVertex>(8);
        foreach (var (i, j, du, dv) in _leaves)
        {
            Triangulate(i, j, du, dv, boundary);
        }

        return _mesh.Build();
    }

    /// <summary>
    /// Keeps the cell whole or cuts it across the direction that is not flat: in u where a curve along u
    /// (its bottom or top edge) strays from its chord, in v where a curve along v does. A cell whose
    /// edges are flat but whose interior is not is cut across the direction whose edges and middle
    /// iso-curve stray most, or both ways when they hardly stray at all (a twist). So a surface curved
    /// more one way than the other gets long thin cells along its flatter direction, not squares.
    /// </summary>
    private void Refine(long i, long j, long du, long dv)
    {
        TwistablePoint a = Point(i, j), b = Point(i + du, j), c = Point(i + du, j + dv), d = Point(i, j + dv);
        var alongU = Math.Max(_probe.EdgeError(i, j, i + du, j, a, b), _probe.EdgeError(i, j + dv, i + du, j + dv, d, c));
        var alongV = Math.Max(_probe.EdgeError(i, j, i, j + dv, a, d), _probe.EdgeError(i + du, j, i + du, j + dv, b, c));
        var limit = _probe.Limit;
        bool splitU = alongU > limit, splitV = alongV > limit;
        long ku = 1, kv = 1;
        if (splitU || splitV)
        {
            // Where one direction is cut alone, the other keeps its gap and this one gets the rest.
            ku = splitU ? Parts(du, Squared(alongU, splitV ? 0.5 * limit : Math.Max(limit - alongV, 0.25 * limit)), i, j) : 1;
            kv = splitV ? Parts(dv, Squared(alongV, splitU ? 0.5 * limit : Math.Max(limit - alongU, 0.25 * limit)), i, j) : 1;
            (ku, kv) = Enough(du, dv, ku, kv, alongU, alongV, _probe.InteriorError(i, j, du, dv, [a, b, c, d]), i, j);
        }
        else
        {
            var inside = _probe.InteriorError(i, j, du, dv, [a, b, c, d]);
            if (inside <= limit)
            {
                _leaves.Add((i, j, du, dv));
                return;
            }

            // The gaps of the two directions add up inside, so cutting across the one that contributes
            // more is often enough, and a finer step than cutting both. When the iso-curves hardly
            // stray, the gap comes from a twist (as in z = uv, or the shear near a pole), which falls
            // in proportion to the length of either side, so one direction is cut then too.
            alongU = Math.Max(alongU, MiddleError(i, j + dv / 2, i + du, j + dv / 2));
            alongV = Math.Max(alongV, MiddleError(i + du / 2, j, i + du / 2, j + dv));
            var twisted = alongU + alongV < TwistShare * inside;
            var wanted = twisted ? inside / limit : Squared(Math.Max(alongU, alongV), Math.Max(limit - Math.Min(alongU, alongV), 0.25 * limit));
            if (alongU >= alongV)
            {
                ku = Parts(du, wanted, i, j);
            }
            else
            {
                kv = Parts(dv, wanted, i, j);
            }
        }

        long su = du / ku, sv = dv / kv;
        for (var x = 0; x <= ku; x++)
        {
            for (var y = 0; y <= kv; y++)
            {
                Vertex(i + x * su, j + y * sv);
            }
        }

        for (var x = 0; x < ku; x++)
        {
            for (var y = 0; y < kv; y++)
            {
                Refine(i + x * su, j + y * sv, su, sv);
            }
        }
    }

    /// <summary>
    /// How many equal parts to cut a side of <paramref name="steps"/> grid steps into, given how many
    /// the gap predicts. A side that wants a few parts is cut at once into that many; a rougher one is
    /// halved and looked at again, since its gap may sit in one small part of it. The parts must divide
    /// the side exactly.
    /// </summary>
    private long Parts(long steps, double wanted, long i, long j)
    {
        var parts = wanted > MaxParts ? 2 : Math.Max(2, (int)Math.Ceiling(wanted));
        for (var k = parts; k <= MaxParts; k++)
        {
            if (steps % k == 0)
            {
                return k;
            }
        }

        for (var k = parts - 1; k >= 2; k--)
        {
            if (steps % k == 0)
            {
                return k;
            }
        }

        var p = _probe.Parameter(i, j);
        throw new TessellationException(FormattableString.Invariant(
            $"The surface does not flatten to tolerance {_options.Tolerance} near (u, v) = ({p.U}, {p.V}): it may have a crease or a jump there, or the tolerance is below its rounding noise."));
    }

    /// <summary>
    /// Adds parts until the children's predicted gap is within the limit. The sags of the two directions
    /// add up inside a cell; what the interior shows beyond them is a twist (as near a pole), which
    /// stands at right angles to the sags and falls with the area of a part, not its square. Without
    /// this, a cell cut just short of enough is cut in two once more, which doubles its triangles.
    /// </summary>
    private (long Ku, long Kv) Enough(long du, long dv, long ku, long kv, double alongU, double alongV, double inside, long i, long j)
    {
        // Inside a cell curved the same way in u and v (a dome) the sags add; in a saddle they cancel,
        // and the interior shows less than their sum. Whatever it shows beyond their sum is twist.
        var sag = alongU + alongV;
        var adding = sag > 0 ? Math.Min(1, inside / sag) : 0;
        var twist = Math.Sqrt(Math.Max(0, inside * inside - sag * sag));
        double Predicted(long pu, long pv)
        {
            double u = alongU / (pu * pu), v = alongV / (pv * pv);
            var bend = Math.Max(Math.Max(u, v), adding * (u + v));
            return Math.Sqrt(bend * bend + Math.Pow(twist / (pu * pv), 2));
        }

        while (Predicted(ku, kv) > _probe.Limit)
        {
            var moreU = alongU / (ku * ku) >= alongV / (kv * kv);
            var next = moreU ? Parts(du, ku + 1, i, j) : Parts(dv, kv + 1, i, j);
            if (next <= (moreU ? ku : kv))
            {
                break; // no finer whole cut at this level: the children look again
            }

            (ku, kv) = moreU ? (next, kv) : (ku, next);
        }

        return (ku, kv);
    }

    /// <summary>Parts a curve needs to bring its gap to the target: a chord's gap shrinks with the square of its length.</summary>
    private static double Squared(double error, double target) => Math.Sqrt(error / target);

    /// <summary>An iso-curve through the middle of a cell; its end points need not be vertices yet.</summary>
    private double MiddleError(long i0, long j0, long i1, long j1)
    {
        SurfaceParameter p0 = _probe.Parameter(i0, j0), p1 = _probe.Parameter(i1, j1);
        return _probe.EdgeError(i0, j0, i1, j1, _sampler.Point(p0.U, p0.V), _sampler.Point(p1.U, p1.V));
    }

    private TwistablePoint Point(long i, long j) => _mesh.Position(Vertex(i, j));

    /// <summary>A leaf's triangles, from its complete boundary: the corners and every sample that finer neighbours placed on its sides.</summary>
    private void Triangulate(long i, long j, long du, long dv, List<BoundaryVertex> boundary)
    {
        AddBoundary(boundary, i, j, i + du, j);
        AddBoundary(boundary, i + du, j, i + du, j + dv);
        AddBoundary(boundary, i + du, j + dv, i, j + dv);
        AddBoundary(boundary, i, j + dv, i, j);
        BoundaryTriangulator.Triangulate(boundary, _mesh);
    }

    /// <summary>The start of the edge and every sample strictly inside it, in order.</summary>
    private void AddBoundary(List<BoundaryVertex> boundary, long i0, long j0, long i1, long j1)
    {
        boundary.Add(new(_vertices[(i0, j0)], i0, j0));
        _lines.Between(i0, j0, i1, j1, boundary);
    }

    /// <summary>
    /// The vertex at grid point (i, j), made on first use. On a pole side it is a copy of the pole's one
    /// vertex; on a seam, the far side's vertex is a copy of the near side's, and making either makes
    /// both, so the faces on the two sides of a seam see the same samples.
    /// </summary>
    private int Vertex(long i, long j)
    {
        if (_vertices.TryGetValue((i, j), out var id))
        {
            return id;
        }

        var m = _resolution;
        var p = _probe.Parameter(i, j);
        (long I, long J)? pole =
            _seams.PoleV0 && j == 0 ? (0, 0)
            : _seams.PoleU0 && i == 0 ? (0, 0)
            : _seams.PoleV1 && j == m ? (0, m)
            : _seams.PoleU1 && i == m ? (m, 0)
            : null;
        if (pole is { } corner)
        {
            id = (i, j) == corner
                ? _mesh.Add(p, _sampler.Point(p.U, p.V), PoleNormal(i, j))
                : _mesh.AddCopy(p, Vertex(corner.I, corner.J));
            Remember(i, j, id);
            return id;
        }

        long ci = _seams.ClosedU && i == m ? 0 : i, cj = _seams.ClosedV && j == m ? 0 : j;
        if ((ci, cj) != (i, j))
        {
            var original = Vertex(ci, cj);
            if (_vertices.TryGetValue((i, j), out id))
            {
                return id; // made as the twin of the original
            }

            id = _mesh.AddCopy(p, original);
            Remember(i, j, id);
            return id;
        }

        id = _mesh.Add(p, _sampler.Point(p.U, p.V), _sampler.UnitNormal(p.U, p.V));
        Remember(i, j, id);
        if (_seams.ClosedU && i == 0)
        {
            Vertex(m, j);
        }

        if (_seams.ClosedV && j == 0)
        {
            Vertex(i, m);
        }

        return id;
    }

    private void Remember(long i, long j, int id)
    {
        _vertices[(i, j)] = id;
        _lines.Add(i, j, id);
    }

    /// <summary>The normal at a pole: the average of the normals just off the pole all around it.</summary>
    private TwistableVector PoleNormal(long i, long j)
    {
        var m = _resolution;
        var around = _seams.PoleV0 && j == 0 ? _seams.AroundPole(true, 0)
            : _seams.PoleU0 && i == 0 ? _seams.AroundPole(false, 0)
            : _seams.PoleV1 && j == m ? _seams.AroundPole(true, 1)
            : _seams.AroundPole(false, 1);
        return SurfaceSampler.Average(around.Select(q => _sampler.UnitNormal(q.U, q.V)));
    }
}
