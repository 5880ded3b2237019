using RayTracer.Cli.Experiments;
using RayTracer.Geometry.Meshes;
using RayTracer.Scenes;
using RayTracer.Scenes.Triangles;
using RayTracer.Viewing;

namespace RayTracer.Tests.Geometry.Solvers;

/// <summary>
/// Each experiment scene rendered small with each test gives Möller–Trumbore's image to within 1e-6 in
/// linear radiance per channel. Measured: at most 1.5e-10 (the Plücker tests on the glass bunny); the
/// rest is rounding in t and the barycentrics carried through refraction and smooth normals.
/// </summary>
[Collection(TriangleTestCollection.Name)]
public sealed class TriangleTests_Render
{
    private const double PixelTolerance = 1e-6;

    public static TheoryData<int> SceneIndices => [0, 1, 2, 3, 4];

    [Theory]
    [MemberData(nameof(SceneIndices))]
    public void Renders_with_every_test_match_moller_trumbore(int index)
    {
        var scene = TriangleTestScenes.Create(detail: 0.01)[index];
        var settings = new SceneSettings { Width = 40, Height = 30 };
        var renderer = new Renderer(new RenderOptions { Threads = 2 });
        scene.Mesh.TriangleTest = TriangleTest.MollerTrumbore;
        var reference = renderer.Render(scene.Build(settings));
        foreach (var test in new[] { TriangleTest.Algebraic, TriangleTest.Plucker, TriangleTest.PluckerEdges })
        {
            scene.Mesh.TriangleTest = test;
            var image = renderer.Render(scene.Build(settings));
            var (max, _) = TrianglesExperiment.Compare(reference, image);
            Assert.True(max <= PixelTolerance, $"{scene.Name} with {test}: largest channel difference {max}");
        }

        // The scene must show the mesh, or the comparison proves nothing.
        var background = scene.Build(settings).BackgroundColor;
        Assert.Contains(reference.Pixels.ToArray(), p => Math.Abs(p.r - background.r) > 0.05);
    }
}
