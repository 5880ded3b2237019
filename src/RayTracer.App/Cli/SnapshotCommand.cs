using System.CommandLine;
using System.Globalization;
using RayTracer.Factories;
using RayTracer.Scenes;
using RayTracer.Viewing;

namespace RayTracer.Cli;

/// <summary>
/// <c>raytracer snapshot</c>: renders every built-in scene (or the named ones) small, with a fixed seed, and
/// writes each image's exact radiance to a folder; with <c>--against</c>, compares with an earlier folder
/// pixel for pixel. This is how a change to the renderer shows that images are unchanged, or how far they moved.
/// </summary>
internal static class SnapshotCommand
{
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var output = new Option<string>("--output", "-o") { Description = "Folder for the snapshots (one .bin per scene)", HelpName = "DIR", Required = true };
        var against = new Option<string?>("--against") { Description = "Folder of earlier snapshots to compare with", HelpName = "DIR" };
        var scenes = new Option<string[]>("--scene") { Description = "Scene to render (repeatable; default: all)", HelpName = "SCENE", AllowMultipleArgumentsPerToken = true };
        var width = Options.Integer("--width", "Image width in pixels [default: 32]", 1, Options.MaxResolution);
        var height = Options.Integer("--height", "Image height in pixels [default: 24]", 1, Options.MaxResolution);
        var samples = Options.Integer("--spp", "Samples per pixel [default: 4]", 1, 65536, "-s");
        var seed = new Option<ulong?>("--seed") { Description = "Seed of every sampler (default 1)", HelpName = "S" };
        var command = new Command("snapshot", "Renders the scenes small with a fixed seed and writes (or compares) their exact radiance.")
        {
            output, against, scenes, width, height, samples, seed,
        };
        command.Validators.Add(result =>
        {
            foreach (var name in result.GetValue(scenes) ?? [])
                if (!SceneFactory.Names.Contains(name, StringComparer.OrdinalIgnoreCase))
                    result.AddError($"unknown scene '{name}' (run 'raytracer list' to see the scenes)");
        });
        command.SetAction(parsed =>
        {
            var names = parsed.GetValue(scenes) is { Length: > 0 } chosen ? chosen : SceneFactory.Names.ToArray();
            var settings = new SceneSettings
            {
                Width = parsed.GetValue(width) ?? 32,
                Height = parsed.GetValue(height) ?? 24,
                SamplesPerPixel = parsed.GetValue(samples) ?? 4,
            };
            return Run(names, settings, parsed.GetValue(seed) ?? 1, parsed.GetValue(output)!, parsed.GetValue(against), stdout, stderr);
        });
        return command;
    }

    private static int Run(string[] names, SceneSettings settings, ulong seed, string folder, string? against, TextWriter stdout, TextWriter stderr)
    {
        Directory.CreateDirectory(folder);
        var differing = 0;
        foreach (var name in names)
        {
            SceneFactory.TryCreate(name, out var scene);
            // Scenes that map an image get none here, so they show their built-in stand-in.
            var world = scene!.Build(settings);
            var image = new Renderer(new RenderOptions { Seed = seed }).Render(world);
            var bytes = SceneSnapshot.Encode(image);
            var path = Path.Combine(folder, scene.Name + ".bin");
            File.WriteAllBytes(path, bytes);
            var line = $"{scene.Name,-28} {image.Width}x{image.Height} {SceneSnapshot.Hash(bytes)}";
            if (against is not null)
            {
                var earlierPath = Path.Combine(against, scene.Name + ".bin");
                if (!File.Exists(earlierPath))
                {
                    stderr.WriteLine($"raytracer: error: {earlierPath}: no such file");
                    return Application.Failure;
                }
                var earlier = File.ReadAllBytes(earlierPath);
                if (earlier.AsSpan().SequenceEqual(bytes))
                    line += " identical";
                else
                {
                    differing++;
                    var (_, _, pixels) = SceneSnapshot.Decode(earlier, earlierPath);
                    var (_, _, now) = SceneSnapshot.Decode(bytes, path);
                    var d = SceneSnapshot.Difference(now, pixels);
                    line += " differs: " + string.Join("  ", d.Select((c, i) => string.Create(CultureInfo.InvariantCulture,
                        $"{"rgb"[i]} |d|={c.MeanAbsolute:G3} d={c.Mean:G3}±{c.StandardError:G2}")));
                }
            }
            stdout.WriteLine(line);
        }
        if (against is not null)
            stdout.WriteLine($"{names.Length - differing} of {names.Length} identical");
        return Application.Ok;
    }
}
