using System.CommandLine;
using System.Globalization;
using RayTracer.Geometry.Meshes;
using RayTracer.Scenes.Triangles;
using SafeFiles;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// <c>raytracer experiments triangles</c>: thesis Table 7-3 and Figures 7-8, 7-9 re-created with the four
/// ray–triangle tests. Writes OUT/triangles.md, its charts and the scene images under OUT/triangles/.
/// </summary>
public static class TrianglesCommand
{
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var output = new Option<string>("--output", "-o") { Description = "Folder of the report (triangles.md and triangles/) [default: bench/results]", HelpName = "DIR" };
        var width = Options.Integer("--width", "Image width in pixels", 8, Options.MaxResolution);
        var height = Options.Integer("--height", "Image height in pixels", 8, Options.MaxResolution);
        var threads = Options.Integer("--threads", "Render threads (default 1, for steady timings)", 1, Options.MaxThreads, "-t");
        var repeats = Options.Integer("--repeats", "Timed runs per scene and test; the best is kept (default 3)", 1, 100);
        var only = new Option<string[]>("--scene") { Description = $"Run only this scene (repeatable): {string.Join(", ", TriangleTestScenes.Names)}", HelpName = "NAME" };
        only.AcceptOnlyFromAmong([.. TriangleTestScenes.Names]);
        var quick = new Option<bool>("--quick") { Description = "Small meshes and images, one run: checks the code paths, not for figures" };

        var command = new Command("triangles", "Table 7-3: the four ray-triangle tests on five mesh scenes under the BIH; writes a Markdown report with charts and images.")
        {
            output, width, height, threads, repeats, only, quick,
        };
        command.SetAction(parsed =>
        {
            var settings = parsed.GetValue(quick) ? TrianglesSettings.Quick : new TrianglesSettings();
            settings = settings with
            {
                Width = parsed.GetValue(width) ?? settings.Width,
                Height = parsed.GetValue(height) ?? settings.Height,
                Threads = parsed.GetValue(threads) ?? settings.Threads,
                Repeats = parsed.GetValue(repeats) ?? settings.Repeats,
                Scenes = parsed.GetValue(only) ?? [],
            };
            var folder = parsed.GetValue(output) ?? Path.Combine("bench", "results");
            var commandLine = "dotnet run -c Release --project src/RayTracer.App -- experiments triangles " + string.Join(' ', parsed.Tokens.Select(t => t.Value).SkipWhile(t => t != "triangles").Skip(1));
            return Run(settings, folder, commandLine.TrimEnd(), stdout, stderr);
        });
        return command;
    }

    public static int Run(TrianglesSettings settings, string folder, string commandLine, TextWriter stdout, TextWriter stderr)
    {
        var images = Path.Combine(folder, TrianglesReport.ImageFolder);
        try
        {
            Directory.CreateDirectory(images);
            var scenes = TriangleTestScenes.Create(settings.Detail, [.. settings.Scenes]);
            var experiment = new TrianglesExperiment(settings)
            {
                Measured = m => stderr.WriteLine(string.Create(CultureInfo.InvariantCulture,
                    $"{m.Scene} {m.Test.Name()}: {m.Triangles:N0} triangles, {m.Rays:N0} rays, {m.TestInvocations:N0} tests, render {m.RenderCpuTime.TotalMilliseconds:F0} ms CPU, nearest hit {m.NearestHitCpuTime.TotalMilliseconds:F0} ms CPU, {m.BytesPerTriangle:F0} B/triangle")),
                Rendered = (scene, world, image) => world.ViewPlane.SaveImage(image, Path.Combine(images, scene.Name + ".png")),
            };
            var results = experiment.Run(scenes);
            OutputFile.Write(Path.Combine(images, "render-time.png"), TrianglesCharts.RelativeTimes(results, r => r.RenderCpuTime, "render CPU time"));
            OutputFile.Write(Path.Combine(images, "nearest-hit-time.png"), TrianglesCharts.RelativeTimes(results, r => r.NearestHitCpuTime, "nearest-hit CPU time"));
            OutputFile.Write(Path.Combine(images, "plucker-gain.png"), TrianglesCharts.PluckerGain(results));
            var report = Path.Combine(folder, "triangles.md");
            OutputFile.Write(report, System.Text.Encoding.UTF8.GetBytes(TrianglesReport.Write(results, scenes, settings, commandLine)));
            stdout.WriteLine(report);
            return Application.Ok;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"raytracer: error: cannot write the report under '{folder}': {e.Message}");
            return Application.Failure;
        }
    }
}
