using RayTracer.Colors;
using RayTracer.Geometry.Meshes;
using RayTracer.Maths;
using RayTracer.Scenes.Meshes;
using RayTracer.Viewing;

namespace RayTracer.Tests.Scenes.Meshes;

/// <summary>
/// The studio frames, lights and grounds a mesh by its bounding sphere, so it is the same picture at any
/// size: a mesh scaled by s must render as the unit one does, however small or large s is.
/// </summary>
public class MeshStudioScene_Scales
{
    private const int Width = 48, Height = 36;

    /// <summary>A regular tetrahedron of edge <paramref name="edge"/>, standing on a face, off the origin by two edges.</summary>
    private static Mesh Tetrahedron(double edge)
    {
        Point3D[] unit = [new(1, 1, 1), new(1, -1, -1), new(-1, 1, -1), new(-1, -1, 1)];
        var scale = edge / Math.Sqrt(8);
        var offset = new Vector3D(2, 0, 1) * edge;
        return new Mesh([.. unit.Select(p => new Point3D(p.x * scale, p.y * scale, p.z * scale) + offset)], [0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2]);
    }

    private static FrameBuffer Render(double edge)
    {
        var world = new MeshStudioScene(Tetrahedron(edge), "tetra").Build(new() { Width = Width, Height = Height, SamplesPerPixel = 1 });
        return new Renderer(new RenderOptions { Seed = 0, Threads = 1 }).Render(world);
    }

    private static bool Near(RGBColor a, RGBColor b) =>
        Math.Abs(a.r - b.r) < 1e-6 && Math.Abs(a.g - b.g) < 1e-6 && Math.Abs(a.b - b.b) < 1e-6;

    /// <summary>
    /// The mesh is the only surface with red equal to green (white lights on <see cref="MeshStudioScene.MeshColor"/>);
    /// the ground is redder and the background greener.
    /// </summary>
    private static bool IsMesh(RGBColor c) => c.g > 0 && Math.Abs(c.r - c.g) <= 1e-9 * c.g;

    [Theory]
    [InlineData(1e-9)]
    [InlineData(1e-8)]
    [InlineData(2e9)]
    [InlineData(1e10)]
    public void A_tiny_or_huge_tetrahedron_renders_as_the_unit_one(double edge)
    {
        var unit = Render(1);
        var scaled = Render(edge);

        // The camera looks at the centre of the bounding sphere, which is inside a tetrahedron.
        foreach (var image in new[] { unit, scaled })
        {
            Assert.True(IsMesh(image[Width / 2, Height / 2]), $"the centre pixel is {image[Width / 2, Height / 2]}, not the mesh");
            Assert.InRange(image.Pixels.ToArray().Count(IsMesh), Width * Height / 20, Width * Height / 2);
        }

        // Rounding differs at other scales, which may move a silhouette by a pixel here and there.
        var differing = Enumerable.Range(0, Width * Height).Count(i => !Near(unit.Pixels[i], scaled.Pixels[i]));
        Assert.True(differing <= Width * Height / 100, $"{differing} of {Width * Height} pixels differ from the unit render");
    }
}
