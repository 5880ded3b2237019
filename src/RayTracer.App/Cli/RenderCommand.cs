using System.CommandLine;
using System.CommandLine.Completions;
using System.Globalization;
using RayTracer.Factories;
using RayTracer.Geometry.Meshes;
using RayTracer.Scenes;
using RayTracer.Scenes.Meshes;
using RayTracer.Viewing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Cli;

/// <summary><c>raytracer render</c>: a built-in scene, or a mesh file in a studio, to a PNG or HDR file.</summary>
internal static class RenderCommand
{
    public static Command Create(TextWriter stdout, TextWriter stderr, bool interactiveProgress)
    {
        var scene = new Argument<string>("scene")
        {
            Description = $"Built-in scene ('raytracer list' shows them) [default: {SceneFactory.DefaultSceneName}]",
            HelpName = "SCENE",
            Arity = ArgumentArity.ZeroOrOne,
        };
        scene.Validators.Add(result =>
        {
            if (result.GetValueOrDefault<string?>() is { } name && !SceneFactory.Names.Contains(name))
                result.AddError($"unknown scene '{name}' (run 'raytracer list' to see the scenes)");
        });
        scene.CompletionSources.Add(_ => SceneFactory.Names.Select(name => new CompletionItem(name)));

        var output = new Option<string>("--output", "-o")
        {
            Description = $"Image to write; the extension chooses the format: {string.Join(" or ", ImageFile.OutputExtensions)}",
            HelpName = "OUT.png",
            Required = true,
        };
        output.Validators.Add(result =>
        {
            if (result.GetValueOrDefault<string>() is { } path && !ImageFile.IsOutputPath(path))
                result.AddError($"cannot write '{path}': extension '{Path.GetExtension(path)}' is not one of {string.Join(", ", ImageFile.OutputExtensions)}");
        });

        var width = Options.Integer("--width", "Image width in pixels", 1, Options.MaxResolution);
        var height = Options.Integer("--height", "Image height in pixels", 1, Options.MaxResolution);
        var samples = Options.Integer("--spp", "Samples per pixel", 1, 65536, "-s", "--samples");
        var seed = new Option<ulong?>("--seed") { Description = "Seed of every sampler; the image depends on it alone (default 0)", HelpName = "S" };
        var threads = Options.Integer("--threads", "Render threads (default: all cores)", 1, Options.MaxThreads, "-t");
        var maxDepth = Options.Integer("--max-depth", "Deepest reflection or refraction traced", 0, ViewPlane.DeepestMaxDepth);
        var image = Options.ExistingFile("--image", $"Image ({ImageFile.ReadableFormats}) mapped by the texture-image scene");
        var mesh = Options.ExistingFile("--mesh", "PLY or STL mesh to render in a default studio instead of a scene", ".ply", ".stl");
        var triangleTest = new Option<string?>("--triangle-test")
        {
            Description = $"Ray-triangle test of the --mesh: {string.Join(", ", TriangleTestNames.All)} [default: moller]",
            HelpName = "TEST",
        };
        triangleTest.AcceptOnlyFromAmong([.. TriangleTestNames.All]);

        var cameraOptions = new CameraOptions();
        var render = new Command("render", "Renders a built-in scene, or a mesh file in a studio, to a PNG or HDR image.")
        {
            scene, output, width, height, samples, seed, threads, maxDepth, image, mesh, triangleTest,
        };
        foreach (var option in cameraOptions.All)
            render.Options.Add(option);
        render.Validators.Add(result =>
        {
            var sceneGiven = result.GetResult(scene) is { Tokens.Count: > 0 };
            var meshGiven = result.GetResult(mesh) is not null;
            var imageGiven = result.GetResult(image) is not null;
            if (meshGiven && sceneGiven)
                result.AddError($"--mesh renders the mesh in its own studio; do not name a scene ('{result.GetValue(scene)}') as well");
            else if (result.GetResult(triangleTest) is not null && !meshGiven)
                result.AddError("--triangle-test applies to --mesh only");
            else if (imageGiven && (meshGiven || !(SceneFactory.TryCreate(result.GetValue(scene) ?? SceneFactory.DefaultSceneName, out var chosen) && chosen.UsesImage)))
                result.AddError($"--image applies to the texture-image scene only");
        });

        render.SetAction(parsed =>
        {
            var request = new RenderRequest
            {
                SceneName = parsed.GetValue(scene) ?? SceneFactory.DefaultSceneName,
                MeshPath = parsed.GetValue(mesh),
                TriangleTest = TriangleTestNames.TryParse(parsed.GetValue(triangleTest), out var test) ? test : TriangleTest.MollerTrumbore,
                Output = parsed.GetValue(output)!,
                Settings = new SceneSettings
                {
                    Width = parsed.GetValue(width),
                    Height = parsed.GetValue(height),
                    SamplesPerPixel = parsed.GetValue(samples),
                    MaxDepth = parsed.GetValue(maxDepth),
                    ImagePath = parsed.GetValue(image),
                },
                Seed = parsed.GetValue(seed) ?? 0,
                Threads = parsed.GetValue(threads) ?? Environment.ProcessorCount,
                Camera = cameraOptions.Read(parsed),
            };
            return Render(request, stdout, stderr, interactiveProgress);
        });
        return render;
    }

    private sealed record RenderRequest
    {
        public required string SceneName { get; init; }
        public required string? MeshPath { get; init; }
        public required TriangleTest TriangleTest { get; init; }
        public required string Output { get; init; }
        public required SceneSettings Settings { get; init; }
        public required ulong Seed { get; init; }
        public required int Threads { get; init; }
        public required CameraRequest Camera { get; init; }
    }

    private static int Render(RenderRequest request, TextWriter stdout, TextWriter stderr, bool interactive)
    {
        SceneDescription scene;
        if (request.MeshPath is { } meshPath)
        {
            if (MeshInput.Read(meshPath, stderr) is not { } mesh)
                return Application.Failure;
            mesh.TriangleTest = request.TriangleTest;
            scene = new MeshStudioScene(mesh, meshPath);
        }
        else if (!SceneFactory.TryCreate(request.SceneName, out scene!))
        {
            // The parser accepts only scene names from the factory, so this is a programming error.
            throw new InvalidOperationException($"unknown scene '{request.SceneName}'");
        }

        World world;
        try
        {
            world = scene.Build(request.Settings);
        }
        catch (ImageFormatException e)
        {
            stderr.WriteLine($"{e.Path}: error: {e.Problem}");
            return Application.Failure;
        }
        catch (Exception e)
        {
            stderr.WriteLine($"raytracer: error: cannot build scene '{scene.Name}': {e.Message}");
            return Application.Failure;
        }

        // Camera options are checked against the scene's own camera, so some mistakes show only now.
        if (request.Camera.ApplyTo(world) is { } cameraError)
        {
            stderr.WriteLine($"raytracer: error: {cameraError}");
            return Application.Usage;
        }

        var progress = new ProgressBar(stderr, interactive);
        var renderer = new Renderer(new RenderOptions { Seed = request.Seed, Threads = request.Threads, Progress = progress.Report });
        RenderResult result;
        try
        {
            result = renderer.RenderWithStatistics(world);
        }
        catch (Exception e)
        {
            // The scene is at fault, not the user; report it without a stack trace and write nothing.
            stderr.WriteLine($"raytracer: error: rendering '{scene.Name}' failed: {e.GetBaseException().Message}");
            return Application.Failure;
        }

        try
        {
            world.ViewPlane.SaveImage(result.Image, request.Output);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"raytracer: error: cannot write '{request.Output}': {e.Message}");
            return Application.Failure;
        }

        stderr.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{scene.Name}: {result.Image.Width}x{result.Image.Height}, {world.ViewPlane.NumSamples} spp, seed {request.Seed}, {request.Threads} thread(s): " +
            $"{result.TotalRays:N0} rays ({result.PrimaryRays:N0} primary) in {result.Elapsed.TotalSeconds:F2} s = {result.MegaRaysPerSecond:F2} Mrays/s"));
        stdout.WriteLine(request.Output);
        return Application.Ok;
    }
}
