using System.CommandLine;
using System.Globalization;
using RayTracer.Acceleration;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Scenes.Meshes;
using RayTracer.Tracing;

namespace RayTracer.Cli;

/// <summary>
/// <c>raytracer bench</c>: build time and ray throughput of the acceleration structures (and Embree's, when
/// installed) on the procedural displaced sphere, or on a mesh file seen through render's studio camera.
/// </summary>
internal static class BenchCommand
{
    public const int DefaultWidth = 1024, DefaultHeight = 768;

    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var triangles = Options.Integer("--triangles", "Triangles of the procedural mesh", 8, 50_000_000);
        var width = Options.Integer("--width", $"Image width in pixels [default: {DefaultWidth}]", 1, Options.MaxResolution);
        var height = Options.Integer("--height", $"Image height in pixels [default: {DefaultHeight}]", 1, Options.MaxResolution);
        var threads = Options.Integer("--threads", "Render threads (default: all cores)", 1, Options.MaxThreads, "-t");
        var mesh = Options.ExistingFile("--mesh", "PLY or STL mesh to measure instead of the procedural one, seen as 'render --mesh' sees it", ".ply", ".stl");
        var cameraOptions = new CameraOptions();
        var bench = new Command("bench",
            "Times building the grid, BIH and BVH over a mesh and their primary-ray throughput, then shadow rays; Embree alongside when libembree3 is installed.")
        {
            triangles, width, height, threads, mesh,
        };
        foreach (var option in cameraOptions.All)
            bench.Options.Add(option);
        bench.Validators.Add(result =>
        {
            var meshGiven = result.GetResult(mesh) is not null;
            if (meshGiven && result.GetResult(triangles) is not null)
                result.AddError("--triangles sizes the procedural mesh; it does not apply to --mesh");
            else if (!meshGiven && cameraOptions.All.Any(o => result.GetResult(o) is not null))
                result.AddError("--camera, --eye, --look-at and --up apply to --mesh only");
        });

        bench.SetAction(parsed =>
        {
            int w = parsed.GetValue(width) ?? DefaultWidth, h = parsed.GetValue(height) ?? DefaultHeight;
            int t = parsed.GetValue(threads) ?? Environment.ProcessorCount;
            if (parsed.GetValue(mesh) is not { } path)
            {
                ThroughputReport.Run(stdout, parsed.GetValue(triangles) ?? 1_000_000, w, h, t);
                return Application.Ok;
            }

            return BenchMesh(path, w, h, t, cameraOptions.Read(parsed), stdout, stderr);
        });
        return bench;
    }

    private static int BenchMesh(string path, int width, int height, int threads, CameraRequest camera, TextWriter stdout, TextWriter stderr)
    {
        if (MeshInput.Read(path, stderr) is not { } mesh)
            return Application.Failure;

        // The studio gives the camera render would use; only its primary rays are kept.
        World world;
        try
        {
            world = new MeshStudioScene(mesh, path).Build(new SceneSettings { Width = width, Height = height, SamplesPerPixel = 1 });
        }
        catch (Exception e) when (e is ArgumentException or InvalidOperationException)
        {
            stderr.WriteLine($"raytracer: error: cannot frame '{path}': {e.Message}");
            return Application.Failure;
        }

        if (camera.ApplyTo(world) is { } cameraError)
        {
            stderr.WriteLine($"raytracer: error: {cameraError}");
            return Application.Usage;
        }

        var rays = CameraRays(world);
        var cameraName = camera.Camera ?? "studio pinhole";
        ThroughputReport.Run(stdout, mesh, path, rays,
            string.Create(CultureInfo.InvariantCulture, $"{rays.Length:N0} primary rays of a {width}x{height} image through the {cameraName} camera, 1 per pixel centre"), threads);
        return Application.Ok;
    }

    /// <summary>The camera's ray through every pixel centre it sees (a fisheye sees a disc), row 0 at the top.</summary>
    public static Ray[] CameraRays(World world)
    {
        var camera = world.Camera ?? throw new InvalidOperationException("The world has no camera.");
        var vp = world.ViewPlane;
        var s = vp.PixelSize;
        var rays = new List<Ray>(vp.HorizontalResolution * vp.VerticalResolution);
        for (int row = 0; row < vp.VerticalResolution; row++)
        {
            int r = vp.VerticalResolution - 1 - row;
            for (int column = 0; column < vp.HorizontalResolution; column++)
            {
                var pp = new Point2D(s * (column - 0.5 * vp.HorizontalResolution + 0.5), s * (r - 0.5 * vp.VerticalResolution + 0.5));
                if (camera.GetRay(pp, vp, out var ray))
                {
                    ray.tMin = world.RayEpsilon;
                    rays.Add(ray);
                }
            }
        }

        return [.. rays];
    }
}
