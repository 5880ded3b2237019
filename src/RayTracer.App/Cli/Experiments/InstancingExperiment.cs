using System.Runtime.InteropServices;
using RayTracer.Geometry;
using RayTracer.Scenes;
using RayTracer.Scenes.Instancing;
using RayTracer.Timing;
using RayTracer.Tracing;
using RayTracer.Viewing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// Thesis §7.2.1 re-created: each scene of Figure 7-3 rendered with each of the five cylinder
/// methods. Per pair one counting render on one thread (every tube wrapped in a counter of its
/// method that also records each test), then the recorded tests asked again of the bare tubes
/// <see cref="Repeats"/> times, the fastest kept, and one render of the bare tubes for the image and
/// its wall time. Memory is measured apart, by building many tubes and weighing the heap.
/// </summary>
internal sealed class InstancingExperiment
{
    /// <summary>An 8-bit difference up to this counts as the same pixel (rounding of the tone mapping).</summary>
    public const int PixelTolerance = 1;

    public static IReadOnlyList<InstancingScene> Scenes(CylinderMethod method, Func<GeometricObject, GeometricObject>? wrap = null) =>
    [
        new InstancingBlocksScene { Method = method, Wrap = wrap },
        new InstancingHelixScene { Method = method, Wrap = wrap },
        new InstancingEpitrochoidScene { Method = method, Wrap = wrap },
        new InstancingColumnScene { Method = method, Wrap = wrap },
    ];

    private static readonly Dictionary<CylinderMethod, InvocationCounter> Counters =
        Enum.GetValues<CylinderMethod>().ToDictionary(m => m, m => new InvocationCounter($"instancing {Label(m)} tests"));

    public required int Width { get; init; }
    public required int Height { get; init; }
    public required int Threads { get; init; }
    /// <summary>Timed replays of the recorded tests; the fastest is kept.</summary>
    public required int Repeats { get; init; }

    /// <summary>Tubes built per method when weighing them.</summary>
    public int MemorySamples { get; init; } = 4000;

    public Action<string>? Progress { get; init; }

    public static string Label(CylinderMethod method) => method switch
    {
        CylinderMethod.UCyl => "U-Cyl",
        CylinderMethod.GauCyl => "GAU-Cyl",
        CylinderMethod.ICyl => "I-Cyl",
        CylinderMethod.TsrCyl => "TSR-Cyl",
        _ => "RSTR-Cyl",
    };

    /// <summary>Runs every scene with every method; <paramref name="images"/> receives each render (scene, method, PNG).</summary>
    public IReadOnlyList<InstancingMeasurement> Run(Action<string, CylinderMethod, PixelImage> images)
    {
        var results = new List<InstancingMeasurement>();
        var methods = Enum.GetValues<CylinderMethod>();
        var sceneCount = Scenes(CylinderMethod.UCyl).Count;
        for (var s = 0; s < sceneCount; s++)
        {
            PixelImage? reference = null;
            foreach (var method in methods)
            {
                var counter = Counters[method];
                counter.Reset();
                var tubes = new List<GeometricObject>();
                var log = new List<InstancingRecordedTest>();
                var counted = Scenes(method, tube =>
                {
                    tubes.Add(tube);
                    return new InstancingCountedObject(tube, counter, tubes.Count - 1, log);
                })[s];
                var countRender = Render(counted, threads: 1);
                var tests = counter.Total;
                var testTime = double.PositiveInfinity;
                for (var r = 0; r < Repeats; r++)
                    testTime = Math.Min(testTime, Replay([.. tubes], log));
                log.Clear();
                log.TrimExcess();

                var scene = Scenes(method)[s];
                var render = Render(scene, Threads);
                reference ??= render.Image;
                var (maxDifference, over) = Compare(reference, render.Image);
                var objects = scene.Cylinders().Count;
                results.Add(new InstancingMeasurement(scene.Name, method, objects, countRender.Rays, tests, testTime,
                    render.Milliseconds, BytesPerObject(scene, method), maxDifference, over));
                images(scene.Name, method, render.Image);
                Progress?.Invoke($"{scene.Name} {Label(method)}: {objects} tubes, {countRender.Rays} rays, {tests} tests, " +
                    $"{testTime:F1} ms in tests, {render.Milliseconds:F0} ms per render");
            }
        }

        return results;
    }

    /// <summary>The largest 8-bit difference of any channel and the number of pixels beyond <see cref="PixelTolerance"/>.</summary>
    public static (int MaxDifference, int PixelsOver) Compare(PixelImage expected, PixelImage actual)
    {
        if (expected.Width != actual.Width || expected.Height != actual.Height || expected.Channels != actual.Channels)
            throw new ArgumentException("The images differ in size.");
        var max = 0;
        var over = 0;
        var channels = expected.Channels;
        for (var i = 0; i < expected.Data.Length; i += channels)
        {
            var pixel = 0;
            for (var c = 0; c < channels; c++)
                pixel = Math.Max(pixel, Math.Abs(expected.Data[i + c] - actual.Data[i + c]));
            max = Math.Max(max, pixel);
            if (pixel > PixelTolerance)
                over++;
        }

        return (max, over);
    }

    private SceneSettings Settings => new() { Width = Width, Height = Height, SamplesPerPixel = 1 };

    private (PixelImage Image, long Rays, double Milliseconds) Render(InstancingScene scene, int threads)
    {
        var world = scene.Build(Settings);
        var result = new Renderer(new RenderOptions { Threads = threads }).RenderWithStatistics(world);
        return (result.Image.ToImage(world.ViewPlane), result.TotalRays, result.Elapsed.TotalMilliseconds);
    }

    /// <summary>
    /// Asks the bare tubes every test recorded in the counting render, in the same order, on one
    /// thread: the time of the tests alone, without traversal or shading, in milliseconds of the
    /// thread's CPU time where the system measures it.
    /// </summary>
    internal static double Replay(GeometricObject[] tubes, List<InstancingRecordedTest> log)
    {
        var sr = new ShadingRecord();
        var sink = 0.0;
        var start = ThreadCpuClock.NowMilliseconds();
        foreach (ref readonly var test in CollectionsMarshal.AsSpan(log))
        {
            var tube = tubes[test.Tube];
            switch (test.Kind)
            {
                case InstancingTestKind.Intersect:
                    if (tube.Intersect(test.Ray, out var t)) sink += t;
                    break;
                case InstancingTestKind.Hit:
                    if (tube.Hit(test.Ray, out var th, sr)) sink += th;
                    break;
                case InstancingTestKind.ShadowHit:
                    if (tube.ShadowHit(test.Ray, out var ts)) sink += ts;
                    break;
                default:
                    if (tube.Occludes(test.Ray, test.MaxDistance)) sink += 1;
                    break;
            }
        }

        var elapsed = ThreadCpuClock.NowMilliseconds() - start;
        // The sum is used so that no test can be dropped as dead code.
        return double.IsNaN(sink) ? double.NaN : elapsed;
    }

    /// <summary>
    /// Bytes that stay on the heap per tube: the scene's tubes are built, cycling through its specs,
    /// into an array made beforehand, with full collections before and after, so the temporaries of
    /// building (frames, twists, matrices composed on the way) and shared materials are not counted.
    /// This is done for <see cref="MemorySamples"/> and for twice as many tubes, and the difference is
    /// divided by <see cref="MemorySamples"/>, so a constant cost of weighing cancels.
    /// </summary>
    private double BytesPerObject(InstancingScene scene, CylinderMethod method)
    {
        var specs = scene.Cylinders();
        long Weigh(int count)
        {
            var kept = new GeometricObject[count];
            var before = GC.GetTotalMemory(forceFullCollection: true);
            for (var i = 0; i < kept.Length; i++)
                kept[i] = specs[i % specs.Count].Create(method);
            var after = GC.GetTotalMemory(forceFullCollection: true);
            GC.KeepAlive(kept);
            return after - before;
        }

        var single = Weigh(MemorySamples);
        var twice = Weigh(2 * MemorySamples);
        return (twice - single) / (double)MemorySamples;
    }
}
