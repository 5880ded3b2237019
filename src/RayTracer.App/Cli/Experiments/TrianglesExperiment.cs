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
            foreach (var measurement in MeasureScene(scene))
            {
                results.Add(measurement);
                Measured?.Invoke(measurement);
            }
        }

        return results;
    }

    /// <summary>One scene with every test. The timed runs take the tests in turn, round after round, so
    /// that a change of load on a shared machine falls on all of them alike.</summary>
    private List<TrianglesMeasurement> MeasureScene(TriangleTestScene scene)
    {
        var runs = new List<TestRun>();
        foreach (var test in Tests)
        {
            scene.Mesh.TriangleTest = test;
            var retained = RetainedBytes(scene.Mesh);
            var world = scene.Build(new SceneSettings { Width = settings.Width, Height = settings.Height });
            runs.Add(new TestRun(test, world, scene.Hierarchy!, retained, NearestHitRays(scene, world)));
        }

        var renderer = new Renderer(new RenderOptions { Seed = 0, Threads = settings.Threads });
        foreach (var run in runs)
        {
            // The first render warms the code up and gives the counts and the image.
            var counter = TriangleTestCounters.For(run.Test);
            counter.Reset();
            run.First = renderer.RenderWithStatistics(run.World);
            run.Invocations = counter.Total;
            NearestHits(run);
        }

        for (var round = 0; round < settings.Repeats; round++)
        {
            foreach (var run in runs)
            {
                var cpu = CpuTime();
                var elapsed = renderer.RenderWithStatistics(run.World).Elapsed;
                run.Render.Add(elapsed, CpuTime() - cpu);
                var (wall, nearestCpu) = NearestHits(run);
                run.NearestHit.Add(wall, nearestCpu);
            }
        }

        var reference = runs[0].First!.Image;
        Rendered?.Invoke(scene, runs[0].World, reference);
        return [.. runs.Select(run =>
        {
            var (maxDifference, differing) = Compare(reference, run.First!.Image);
            return new TrianglesMeasurement
            {
                Scene = scene.Name,
                Test = run.Test,
                Triangles = scene.Mesh.TriangleCount,
                Rays = run.First.TotalRays,
                TestInvocations = run.Invocations,
                RenderTime = run.Render.Wall,
                RenderCpuTime = run.Render.Cpu,
                NearestHitTime = run.NearestHit.Wall,
                NearestHitCpuTime = run.NearestHit.Cpu,
                NearestHitRays = run.Rays.Length,
                RetainedBytes = run.RetainedBytes,
                MaxPixelDifference = maxDifference,
                DifferingPixels = differing,
            };
        })];
    }

    private static TimeSpan CpuTime() => Process.GetCurrentProcess().TotalProcessorTime;

    /// <summary>The best wall and CPU times seen.</summary>
    private sealed class Best
    {
        public TimeSpan Wall { get; private set; } = TimeSpan.MaxValue;
        public TimeSpan Cpu { get; private set; } = TimeSpan.MaxValue;

        public void Add(TimeSpan wall, TimeSpan cpu)
        {
            Wall = wall < Wall ? wall : Wall;
            Cpu = cpu < Cpu ? cpu : Cpu;
        }
    }

    private sealed class TestRun(TriangleTest test, World world, Acceleration.BoundingIntervalHierarchy hierarchy, long retainedBytes, Ray[] rays)
    {
        public TriangleTest Test { get; } = test;
        public World World { get; } = world;
        public Acceleration.BoundingIntervalHierarchy Hierarchy { get; } = hierarchy;
        public long RetainedBytes { get; } = retainedBytes;
        public Ray[] Rays { get; } = rays;
        public RenderResult? First { get; set; }
        public long Invocations { get; set; }
        public Best Render { get; } = new();
        public Best NearestHit { get; } = new();
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

    /// <summary>Rays from the camera's eye towards seeded random points of the mesh's bounds.</summary>
    private Ray[] NearestHitRays(TriangleTestScene scene, World world)
    {
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

        return rays;
    }

    /// <summary>Nearest-hit queries alone (BIH traversal and tests) on this thread: wall and CPU time.</summary>
    private static (TimeSpan Wall, TimeSpan Cpu) NearestHits(TestRun run)
    {
        var cpu = CpuTime();
        var watch = Stopwatch.StartNew();
        var hits = 0;
        foreach (var ray in run.Rays)
            if (run.Hierarchy.IntersectNearest(ray, double.PositiveInfinity, out _, out _))
                hits++;
        watch.Stop();
        GC.KeepAlive(hits);
        return (watch.Elapsed, CpuTime() - cpu);
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
