namespace Twister.Tessellation;

/// <summary>
/// One run of <see cref="SurfaceTessellator"/>. Faces are squares of the parameter grid, refined as a
/// quadtree; vertices sit at dyadic parameters, keyed by integer coordinates so that a sample made by
/// one face is found by every face whose edge passes through it.
/// </summary>
internal sealed class SurfaceTessellation
{
    /// <summary>Halvings available below a starting cell: parameters are multiples of 1 / (cells · 2^Levels).</summary>
    private const int Levels = 30;

    private readonly SurfaceSampler _sampler;
    private readonly TessellationOptions _options;
    private readonly MeshBuilder _mesh;
    private readonly ProbeRandom _random;
    private readonly double _limit;
    private readonly long _resolution;
    private readonly Dictionary<(long I, long J), int> _vertices = [];
    private readonly List<(long I, long J, long Size)> _leaves = [];
    private Seams _seams = new(1);

    public SurfaceTessellation(IParametricSurface surface, TessellationOptions options)
    {
        _sampler = new SurfaceSampler(surface);
        _options = options;
        _mesh = new MeshBuilder(options);
        _random = new ProbeRandom(options.Seed);
        _limit = Acceptance.Fraction * options.Tolerance;
        _resolution = (long)options.InitialCells << Levels;
    }

    public TriangleMesh Run()
    {
        _seams = SeamDetector.Detect(_sampler, _options.InitialCells, _random);
        _sampler.NormalScale = _seams.NormalScale;
        var size = 1L << Levels;
        for (var i = 0; i < _options.InitialCells; i++)
        {
            for (var j = 0; j < _options.InitialCells; j++)
            {
                Refine(i * size, j * size, size);
            }
        }

        foreach (var (i, j, s) in _leaves)
        {
            Triangulate(i, j, s);
        }

        return _mesh.Build();
    }

    private void Refine(long i, long j, long size)
    {
        if (FaceIsFlat(i, j, size))
        {
            _leaves.Add((i, j, size));
            return;
        }

        if (size == 1)
        {
            throw new TessellationException(FormattableString.Invariant(
                $"The surface does not flatten to tolerance {_options.Tolerance} near (u, v) = ({Parameter(i, j).U}, {Parameter(i, j).V}): it may have a crease or a jump there, or the tolerance is below its rounding noise."));
        }

        // Every split makes the midpoints of all four edges, so a sample inside an edge always comes
        // with the midpoint of that edge; BoundaryOf relies on it.
        var h = size / 2;
        Vertex(i + h, j);
        Vertex(i + size, j + h);
        Vertex(i + h, j + size);
        Vertex(i, j + h);
        Vertex(i + h, j + h);
        Refine(i, j, h);
        Refine(i + h, j, h);
        Refine(i + h, j + h, h);
        Refine(i, j + h, h);
    }

    /// <summary>
    /// Whether the face may stay whole: each edge is within the tolerance of its chord (probed as a
    /// curve), and the interior is within the tolerance both of the two triangles cut along the
    /// diagonal and of the four triangles fanned from the centre, the two ways a leaf is triangulated.
    /// </summary>
    private bool FaceIsFlat(long i, long j, long size)
    {
        int a = Vertex(i, j), b = Vertex(i + size, j), c = Vertex(i + size, j + size), d = Vertex(i, j + size);
        if (!EdgeIsFlat(a, b) || !EdgeIsFlat(b, c) || !EdgeIsFlat(c, d) || !EdgeIsFlat(d, a)
            || !TriangleIsFlat(a, b, c) || !TriangleIsFlat(a, c, d))
        {
            return false;
        }

        var g = Parameter(i + size / 2, j + size / 2);
        var centre = _sampler.Point(g.U, g.V);
        foreach (var (p, q) in new[] { (a, b), (b, c), (c, d), (d, a) })
        {
            SurfaceParameter pp = _mesh.Parameter(p), pq = _mesh.Parameter(q);
            var onSurface = _sampler.Point((g.U + pp.U + pq.U) / 3, (g.V + pp.V + pq.V) / 3);
            if (Geometry3.Distance(onSurface, Geometry3.Barycentric(centre, _mesh.Position(p), _mesh.Position(q), 1.0 / 3, 1.0 / 3)) > _limit)
            {
                return false;
            }
        }

        return true;
    }

    private bool EdgeIsFlat(int start, int end)
    {
        SurfaceParameter pa = _mesh.Parameter(start), pb = _mesh.Parameter(end);
        TwistablePoint a = _mesh.Position(start), b = _mesh.Position(end);
        var n = _options.ProbeCount;
        for (var k = 0; k < n; k++)
        {
            var s = (k + _random.NextDouble()) / n;
            var q = _sampler.Point(pa.U + s * (pb.U - pa.U), pa.V + s * (pb.V - pa.V));
            if (Geometry3.Distance(q, Geometry3.Lerp(a, b, s)) > _limit)
            {
                return false;
            }
        }

        return true;
    }

    private bool TriangleIsFlat(int a, int b, int c)
    {
        SurfaceParameter pa = _mesh.Parameter(a), pb = _mesh.Parameter(b), pc = _mesh.Parameter(c);
        TwistablePoint qa = _mesh.Position(a), qb = _mesh.Position(b), qc = _mesh.Position(c);
        for (var k = 0; k <= _options.ProbeCount; k++)
        {
            // The centroid first, where a bump between flat edges shows most, then random points.
            double beta = 1.0 / 3, gamma = 1.0 / 3;
            if (k > 0)
            {
                beta = _random.NextDouble();
                gamma = _random.NextDouble();
                if (beta + gamma > 1)
                {
                    (beta, gamma) = (1 - beta, 1 - gamma);
                }
            }

            var alpha = 1 - beta - gamma;
            var q = _sampler.Point(alpha * pa.U + beta * pb.U + gamma * pc.U, alpha * pa.V + beta * pb.V + gamma * pc.V);
            if (Geometry3.Distance(q, Geometry3.Barycentric(qa, qb, qc, beta, gamma)) > _limit)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>
    /// A leaf's triangles, from its complete boundary: the corners and every sample that finer
    /// neighbours placed on its edges. With no such samples, two triangles along the diagonal; with
    /// some, a fan from the centre through all of them, so a shared edge is cut the same way on both
    /// sides and no vertex is left hanging in the middle of an edge.
    /// </summary>
    private void Triangulate(long i, long j, long size)
    {
        var boundary = new List<int>(8);
        AddBoundary(boundary, i, j, i + size, j);
        AddBoundary(boundary, i + size, j, i + size, j + size);
        AddBoundary(boundary, i + size, j + size, i, j + size);
        AddBoundary(boundary, i, j + size, i, j);
        if (boundary.Count == 4)
        {
            _mesh.AddTriangle(boundary[0], boundary[1], boundary[2]);
            _mesh.AddTriangle(boundary[0], boundary[2], boundary[3]);
            return;
        }

        var centre = Vertex(i + size / 2, j + size / 2);
        for (var k = 0; k < boundary.Count; k++)
        {
            _mesh.AddTriangle(centre, boundary[k], boundary[(k + 1) % boundary.Count]);
        }
    }

    /// <summary>The start of the edge and every sample strictly inside it, in order.</summary>
    private void AddBoundary(List<int> boundary, long i0, long j0, long i1, long j1)
    {
        boundary.Add(_vertices[(i0, j0)]);
        AddInterior(boundary, i0, j0, i1, j1);
    }

    private void AddInterior(List<int> boundary, long i0, long j0, long i1, long j1)
    {
        long mi = (i0 + i1) / 2, mj = (j0 + j1) / 2;
        if ((Math.Abs(i1 - i0) < 2 && Math.Abs(j1 - j0) < 2) || !_vertices.TryGetValue((mi, mj), out var mid))
        {
            return;
        }

        AddInterior(boundary, i0, j0, mi, mj);
        boundary.Add(mid);
        AddInterior(boundary, mi, mj, i1, j1);
    }

    private SurfaceParameter Parameter(long i, long j) => new((double)i / _resolution, (double)j / _resolution);

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
        var p = Parameter(i, j);
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
            _vertices[(i, j)] = id;
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
            _vertices[(i, j)] = id;
            return id;
        }

        id = _mesh.Add(p, _sampler.Point(p.U, p.V), _sampler.UnitNormal(p.U, p.V));
        _vertices[(i, j)] = id;
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
