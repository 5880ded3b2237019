using System.Globalization;
using RayTracer.Acceleration;
using RayTracer.Factories;
using RayTracer.Scenes;
using RayTracer.Viewing;

namespace RayTracer.Cli;

/// <summary>The <c>raytracer</c> command line: list, render and bench. Exit codes: 0 ok, 1 failure, 2 usage.</summary>
public static class Application
{
    public const int Ok = 0, Failure = 1, Usage = 2;

    public const string UsageText = """
        usage:
          raytracer list
          raytracer render [SCENE] -o OUT.png [--width W] [--height H] [--spp N] [--seed S] [--threads T] [--max-depth D] [--image IMG.png]
          raytracer bench [--triangles N] [--width W] [--height H] [--threads T]
        SCENE defaults to 'spheres'; 'raytracer list' shows all scenes. --image maps a PNG in texture-image.
        --max-depth is at most 100; rays whose throughput falls below 1e-5 are not traced, whatever the depth.
        """;

    public static int Run(string[] args, TextWriter stdout, TextWriter stderr, bool interactiveProgress = false)
    {
        try
        {
            if (args.Length == 0)
                throw new UsageException("no command given");
            if (args[0] is "-h" or "--help" or "help")
            {
                stdout.WriteLine(UsageText);
                return Ok;
            }
            return args[0] switch
            {
                "list" => List(args[1..], stdout),
                "render" => Render(args[1..], stdout, stderr, interactiveProgress),
                "bench" => Bench(args[1..], stdout),
                _ => throw new UsageException($"unknown command '{args[0]}'"),
            };
        }
        catch (UsageException e)
        {
            stderr.WriteLine($"raytracer: error: {e.Message}");
            stderr.WriteLine(UsageText);
            return Usage;
        }
    }

    private static int List(string[] args, TextWriter stdout)
    {
        if (args.Length > 0)
            throw new UsageException("list takes no arguments");
        var scenes = SceneFactory.All;
        var width = scenes.Max(s => s.Name.Length);
        foreach (var scene in scenes)
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{scene.Name.PadRight(width)}  {scene.DefaultWidth}x{scene.DefaultHeight} {scene.DefaultSamples,3} spp  {scene.Description}"));
        return Ok;
    }

    private static readonly Dictionary<string, string> Aliases = new() { ["-o"] = "--output", ["-s"] = "--spp", ["-t"] = "--threads" };

    private static int Render(string[] args, TextWriter stdout, TextWriter stderr, bool interactive)
    {
        var options = new OptionReader(args, Aliases,
            new HashSet<string> { "--output", "--width", "--height", "--spp", "--seed", "--threads", "--max-depth", "--image" });
        if (options.Positionals.Count > 1)
            throw new UsageException($"render takes one scene name, got: {string.Join(' ', options.Positionals)}");
        var sceneName = options.Positionals.Count == 1 ? options.Positionals[0] : SceneFactory.DefaultSceneName;
        var output = options.GetString("--output") ?? throw new UsageException("render needs an output file: -o OUT.png");
        if (!output.EndsWith(".png", StringComparison.OrdinalIgnoreCase))
            throw new UsageException($"output file must end in .png, got '{output}'");
        var settings = new SceneSettings
        {
            Width = options.GetInt("--width", 1, 16384),
            Height = options.GetInt("--height", 1, 16384),
            SamplesPerPixel = options.GetInt("--spp", 1, 65536),
            MaxDepth = options.GetInt("--max-depth", 0, ViewPlane.DeepestMaxDepth),
            ImagePath = options.GetString("--image"),
        };
        var seed = options.GetULong("--seed") ?? 0;
        var threads = options.GetInt("--threads", 1, 1024) ?? Environment.ProcessorCount;
        if (!SceneFactory.TryCreate(sceneName, out var scene))
            throw new UsageException($"unknown scene '{sceneName}' (run 'raytracer list' to see the scenes)");
        if (settings.ImagePath is not null && !scene.UsesImage)
            throw new UsageException($"scene '{scene.Name}' has no image texture; --image applies to texture-image");

        World world;
        try
        {
            world = scene.Build(settings);
        }
        catch (Exception e)
        {
            stderr.WriteLine($"raytracer: error: cannot build scene '{scene.Name}': {e.Message}");
            return Failure;
        }

        var progress = new ProgressBar(stderr, interactive);
        var renderer = new Renderer(new RenderOptions { Seed = seed, Threads = threads, Progress = progress.Report });
        RenderResult result;
        try
        {
            result = renderer.RenderWithStatistics(world);
        }
        catch (Exception e)
        {
            // The scene is at fault, not the user; report it without a stack trace and write nothing.
            stderr.WriteLine($"raytracer: error: rendering '{scene.Name}' failed: {e.GetBaseException().Message}");
            return Failure;
        }
        try
        {
            world.ViewPlane.SaveImage(result.Image, output);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"raytracer: error: cannot write '{output}': {e.Message}");
            return Failure;
        }

        var vp = world.ViewPlane;
        stderr.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{scene.Name}: {result.Image.Width}x{result.Image.Height}, {vp.NumSamples} spp, seed {seed}, {threads} thread(s): " +
            $"{result.TotalRays:N0} rays ({result.PrimaryRays:N0} primary) in {result.Elapsed.TotalSeconds:F2} s = {result.MegaRaysPerSecond:F2} Mrays/s"));
        stdout.WriteLine(output);
        return Ok;
    }

    private static int Bench(string[] args, TextWriter stdout)
    {
        var options = new OptionReader(args, Aliases, new HashSet<string> { "--triangles", "--width", "--height", "--threads" });
        if (options.Positionals.Count > 0)
            throw new UsageException($"bench takes no positional arguments, got: {string.Join(' ', options.Positionals)}");
        ThroughputReport.Run(stdout,
            options.GetInt("--triangles", 8, 50_000_000) ?? 1_000_000,
            options.GetInt("--width", 1, 16384) ?? 1024,
            options.GetInt("--height", 1, 16384) ?? 768,
            options.GetInt("--threads", 1, 1024) ?? Environment.ProcessorCount);
        return Ok;
    }
}
