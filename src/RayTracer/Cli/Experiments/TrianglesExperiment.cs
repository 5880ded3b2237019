using System.Diagnostics;
using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Scenes;
using RayTracer.Scenes.Triangles;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// Thesis §7.2.2: each mesh scene rendered with each ray–triangle test under the BIH. Per scene and test it
/// measures rays, test invocations, render time, nearest-hit time and the memory of the triangles.
/// </summary>
public sealed class TrianglesExperiment(TrianglesSettings settings)
{
    public static IReadOnlyList<TriangleTest> Tests { get; } = Enum.GetValues<TriangleTest>();

    /// <summary>Called with each finished measurement (for progress), and with each scene's Möller–Trumbore image.</summary>
    public Action<TrianglesMeasurement>? Measured { get; init; }

    public Action<TriangleTestScene, World, FrameBuffer>? Rendered { get; init; }

    public IReadOnlyList<TrianglesMeasurement> Run(IReadOnlyList<TriangleTestScene> scenes)
    {
        var results = new List<TrianglesMeasurement>();
        foreach (var scene in scenes)
        {
            FrameBuffer? reference = null;
            foreach (var test in Tests)
            {
                var measurement = Measure(scene, test, ref reference);
                results.Add(measurement);
                Measured?.Invoke(measurement);
            }
        }

        return results;
    }

    private TrianglesMeasurement Measure(TriangleTestScene scene, TriangleTest test, ref FrameBuffer? reference)
    {
        scene.Mesh.TriangleTest = test;
        var retained = RetainedBytes(scene.Mesh);
        var world = scene.Build(new SceneSettings { Width = settings.Width, Height = settings.Height });
        var renderer = new Renderer(new RenderOptions { Seed = 0, Threads = settings.Threads });
        var counter = TriangleTestCounters.For(test);

        // The first render warms the code up and gives the counts and the image; the timed ones follow.
        counter.Reset();
        var first = renderer.RenderWithStatistics(world);
        var invocations = counter.Total;
        var best = TimeSpan.MaxValue;
        for (var r = 0; r < settings.Repeats; r++)
        {
            var elapsed = renderer.RenderWithStatistics(world).Elapsed;
            if (elapsed < best)
                best = elapsed;
        }

        double maxDifference = 0;
        var differing = 0;
        if (reference is null)
        {
            reference = first.Image;
            Rendered?.Invoke(scene, world, first.Image);
        }
        else
        {
            (maxDifference, differing) = Compare(reference, first.Image);
        }

        return new TrianglesMeasurement
        {
            Scene = scene.Name,
            Test = test,
            Triangles = scene.Mesh.TriangleCount,
            Rays = first.TotalRays,
            TestInvocations = invocations,
            RenderTime = best,
            NearestHitTime = NearestHitTime(scene, world),
            NearestHitRays = settings.NearestHitRays,
            RetainedBytes = retained,
            MaxPixelDifference = maxDifference,
            DifferingPixels = differing,
        };
    }

    /// <summary>The heap that a BIH over the mesh's triangles keeps alive, after full collections on both sides.</summary>
    private static long RetainedBytes(Mesh mesh)
    {
        var before = GC.GetTotalMemory(forceFullCollection: true);
        var hierarchy = new Acceleration.BoundingIntervalHierarchy(mesh.CreateTriangles(smooth: true));
        var after = GC.GetTotalMemory(forceFullCollection: true);
        GC.KeepAlive(hierarchy);
        return after - before;
    }

    /// <summary>Nearest hits of rays from the camera's eye towards seeded random points of the mesh's bounds.</summary>
    private TimeSpan NearestHitTime(TriangleTestScene scene, World world)
    {
        var hierarchy = scene.Hierarchy!;
        var eye = world.Camera!.Eye;
        var box = scene.Mesh.Bounds;
        var random = new SeededRandom(17);
        var rays = new Ray[settings.NearestHitRays];
        for (var i = 0; i < rays.Length; i++)
        {
            var target = new Point3D(
                box.Min.x + random.NextDouble() * (box.Max.x - box.Min.x),
                box.Min.y + random.NextDouble() * (box.Max.y - box.Min.y),
                box.Min.z + random.NextDouble() * (box.Max.z - box.Min.z));
            rays[i] = new Ray(eye, (target - eye).Normalized());
        }

        var best = TimeSpan.MaxValue;
        for (var r = 0; r <= settings.Repeats; r++)
        {
            var watch = Stopwatch.StartNew();
            var hits = 0;
            foreach (var ray in rays)
                if (hierarchy.IntersectNearest(ray, double.PositiveInfinity, out _, out _))
                    hits++;
            watch.Stop();
            GC.KeepAlive(hits);
            if (r > 0 && watch.Elapsed < best)
                best = watch.Elapsed; // the first pass warms up
        }

        return best;
    }

    /// <summary>Largest channel difference in linear radiance and the number of pixels that differ at all.</summary>
    public static (double Max, int Pixels) Compare(FrameBuffer a, FrameBuffer b)
    {
        double max = 0;
        var pixels = 0;
        var pa = a.Pixels;
        var pb = b.Pixels;
        for (var i = 0; i < pa.Length; i++)
        {
            var d = Math.Max(Math.Abs(pa[i].r - pb[i].r), Math.Max(Math.Abs(pa[i].g - pb[i].g), Math.Abs(pa[i].b - pb[i].b)));
            if (d > 0)
                pixels++;
            max = Math.Max(max, d);
        }

        return (max, pixels);
    }
}
