using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using Twister;

namespace RayTracer.Scenes.Triangles;

/// <summary>
/// The five mesh scenes of the ray–triangle experiment, standing for thesis Figure 7-8 at about its
/// triangle counts: a glass bunny (the Stanford bunny, subdivided), a glass seashell for the glass
/// hand, a mirror twisted column for the pyramob, a displaced torus for the horse and a displaced
/// sphere for the dragon. <c>detail</c> scales every count (1 = the thesis's counts).
/// </summary>
public static class TriangleTestScenes
{
    public static IReadOnlyList<string> Names { get; } = ["glass-bunny", "glass-shell", "mirror-column", "bumpy-torus", "bumpy-sphere"];

    /// <summary>The scenes named in <paramref name="only"/> (all when null or empty), in catalogue order.</summary>
    public static IReadOnlyList<TriangleTestScene> Create(double detail = 1, IReadOnlyCollection<string>? only = null)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(detail);
        return [.. Names.Where(name => only is null || only.Count == 0 || only.Contains(name)).Select(name => Create(name, detail))];
    }

    private static TriangleTestScene Create(string name, double detail) => name switch
    {
        "glass-bunny" => new TriangleTestScene(name, "The Stanford bunny, subdivided, in glass", Bunny(detail), "Transparent bunny", 69_451)
            .With(MaterialFactory.Glass(new RGBColor(0.9, 0.97, 0.92))),
        "glass-shell" => new TriangleTestScene(name, "A Twister seashell in glass", Grid(GlassShell(), 654_666 * detail), "Transparent hand", 654_666) { Elevation = 30 }
            .With(MaterialFactory.Glass(new RGBColor(0.95, 0.9, 0.85))),
        "mirror-column" => new TriangleTestScene(name, "A twisted Twister column as a mirror", Grid(MirrorColumn(), 31_460 * detail), "Pyramob", 31_460)
            .With(MaterialFactory.Mirror(new RGBColor(0.9, 0.85, 0.7), 0.8)),
        "bumpy-torus" => new TriangleTestScene(name, "A displaced Twister torus, smooth shaded", Grid(BumpyTorus(), 96_966 * detail), "Horse", 96_966) { Elevation = 35 }
            .With(MaterialFactory.Plastic(new RGBColor(0.75, 0.45, 0.25), 40)),
        "bumpy-sphere" => new TriangleTestScene(name, "A displaced sphere, smooth shaded", Acceleration.ThroughputReport.DisplacedSphere((int)Math.Max(200, 871_414 * detail)), "Dragon", 871_414)
            .With(MaterialFactory.Shiny(new RGBColor(0.35, 0.6, 0.4))),
        _ => throw new ArgumentException($"unknown scene '{name}'", nameof(name)),
    };

    /// <summary>The committed bunny (3,674 triangles), subdivided while that stays at or under the asked count.</summary>
    public static Mesh Bunny(double detail = 1)
    {
        var mesh = MeshSubdivision.Outward(ReadBunny());
        while (mesh.TriangleCount * 4 <= 69_451 * detail * 1.2)
            mesh = MeshSubdivision.Subdivide(mesh);
        return mesh;
    }

    /// <summary>The bunny as committed in Assets/Bunny/bunny.ply (see the ATTRIBUTION.md beside it).</summary>
    public static Mesh ReadBunny()
    {
        using var stream = typeof(TriangleTestScenes).Assembly.GetManifestResourceStream("Assets/Bunny/bunny.ply")
            ?? throw new InvalidOperationException("the bunny mesh is not embedded in the assembly");
        return PlyReader.Read(stream, "bunny.ply");
    }

    private sealed record GridSurface(IParametricSurface Surface, double Aspect, Func<double, double, double>? Height);

    /// <summary>Five whorls of a shrinking shell.</summary>
    private static GridSurface GlassShell() => new(TwistSurfaces.Seashell(0.5, 0.3, 4, 3, -0.9), 0.2, null);

    /// <summary>A six-lobed column turned half a turn on its way up, with fine flutes.</summary>
    private static GridSurface MirrorColumn() => new(
        TwistSurfaces.TwistedColumn(TwistCurves.Epitrochoid(0.36, 0.06, 0.04, 1), 1.6, Math.PI),
        4, (u, _) => 0.006 * Math.Sin(2 * Math.PI * 48 * u));

    /// <summary>A torus with bumps in both directions.</summary>
    private static GridSurface BumpyTorus() => new(
        TwistSurfaces.Torus(1, 0.4), 0.5, (u, v) => 0.03 * Math.Sin(2 * Math.PI * 9 * u) * Math.Sin(2 * Math.PI * 23 * v));

    /// <summary>uSteps · vSteps · 2 ≈ triangles, with vSteps / uSteps ≈ 1 / aspect, turned from z up to y up.</summary>
    private static Mesh Grid(GridSurface grid, double triangles)
    {
        var u = Math.Max(4, (int)Math.Round(Math.Sqrt(triangles / 2 * grid.Aspect)));
        var v = Math.Max(4, (int)Math.Round(triangles / 2 / u));
        var mesh = ParametricGridMesh.Create(grid.Surface, u, v, grid.Height);
        var vertices = mesh.Vertices.Select(p => new Point3D(p.x, p.z, -p.y)).ToArray();
        var upright = new Mesh(vertices, mesh.Indices);
        upright.ComputeVertexNormals();
        return upright;
    }
}
