using System.Diagnostics;
using RayTracer.Sampling;
using RayTracer.Scenes;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>
/// Renders a world tile by tile in parallel. Every pixel reseeds the thread's random stream from
/// (seed, pixel index), so the result does not depend on the number of threads or the tile order.
/// </summary>
public sealed class Renderer
{
    public Renderer(RenderOptions? options = null)
    {
        Options = options ?? new RenderOptions();
    }

    public RenderOptions Options { get; }

    public FrameBuffer Render(World world) => RenderWithStatistics(world).Image;

    public RenderResult RenderWithStatistics(World world)
    {
        var camera = world.Camera ?? throw new InvalidOperationException("The world has no camera.");
        var integrator = world.Integrator ?? throw new InvalidOperationException("The world has no integrator.");
        var vp = world.ViewPlane;
        var width = camera.ImageWidth(vp);
        var height = camera.ImageHeight(vp);
        var image = new FrameBuffer(width, height);
        var tile = Math.Max(1, Options.TileSize);
        var tilesX = (width + tile - 1) / tile;
        var tilesY = (height + tile - 1) / tile;
        var tileCount = tilesX * tilesY;
        long primary = 0, total = 0;
        var done = 0;

        var parallel = new ParallelOptions
        {
            MaxDegreeOfParallelism = Options.Threads > 0 ? Options.Threads : Environment.ProcessorCount,
            CancellationToken = Options.Cancellation,
        };
        var clock = Stopwatch.StartNew();
        Parallel.For(0, tileCount, parallel, t =>
        {
            var (p0, r0) = RayStatistics.Snapshot();
            var x0 = t % tilesX * tile;
            var y0 = t / tilesX * tile;
            var x1 = Math.Min(width, x0 + tile);
            var y1 = Math.Min(height, y0 + tile);
            for (var row = y0; row < y1; row++)
            for (var column = x0; column < x1; column++)
            {
                SamplingContext.BeginPixel(Options.Seed, (ulong)row * (ulong)width + (ulong)column);
                image[column, row] = integrator.RenderPixel(camera, column, row);
            }
            var (p1, r1) = RayStatistics.Snapshot();
            Interlocked.Add(ref primary, p1 - p0);
            Interlocked.Add(ref total, r1 - r0);
            var finished = Interlocked.Increment(ref done);
            Options.Progress?.Invoke(finished, tileCount);
        });
        clock.Stop();
        return new RenderResult(image, primary, total, clock.Elapsed);
    }
}
