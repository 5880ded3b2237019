namespace Twister.Tessellation;

/// <summary>Collects vertices and triangles and enforces the triangle budget as they arrive.</summary>
internal sealed class MeshBuilder(TessellationOptions options)
{
    private readonly List<TwistablePoint> _positions = [];
    private readonly List<TwistableVector> _normals = [];
    private readonly List<SurfaceParameter> _parameters = [];
    private readonly List<int> _welded = [];
    private readonly List<int> _indices = [];

    public TwistablePoint Position(int vertex) => _positions[vertex];

    public SurfaceParameter Parameter(int vertex) => _parameters[vertex];

    public int Add(SurfaceParameter parameter, TwistablePoint position, TwistableVector normal)
    {
        // A mesh has about half as many vertices as triangles, so this stops a runaway refinement
        // long before the triangles are made.
        if (_positions.Count >= options.MaxTriangles)
        {
            throw OverBudget();
        }

        _positions.Add(position);
        _normals.Add(normal);
        _parameters.Add(parameter);
        _welded.Add(_welded.Count);
        return _positions.Count - 1;
    }

    /// <summary>A vertex at other parameters that stands on the same point as <paramref name="original"/> (a seam or a pole).</summary>
    public int AddCopy(SurfaceParameter parameter, int original)
    {
        var copy = Add(parameter, _positions[original], _normals[original]);
        _welded[copy] = _welded[original];
        return copy;
    }

    public void SetNormal(int vertex, TwistableVector normal) => _normals[vertex] = normal;

    public void AddTriangle(int a, int b, int c)
    {
        int wa = _welded[a], wb = _welded[b], wc = _welded[c];
        if (wa == wb || wb == wc || wc == wa)
        {
            return; // two corners on one pole: a segment, not a triangle
        }

        if (_indices.Count / 3 >= options.MaxTriangles)
        {
            throw OverBudget();
        }

        _indices.Add(a);
        _indices.Add(b);
        _indices.Add(c);
    }

    public TriangleMesh Build() => new([.. _positions], [.. _normals], [.. _parameters], [.. _indices], [.. _welded]);

    private TessellationException OverBudget() => new(FormattableString.Invariant(
        $"Tessellating the surface to tolerance {options.Tolerance} needs more than the budget of {options.MaxTriangles} triangles; raise the tolerance or the budget."));
}
