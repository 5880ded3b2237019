using System.CommandLine;
using RayTracer.Scenes.Instancing;
using RayTracer.Viewing.Imaging;
using SafeFiles;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// <c>raytracer experiments instancing</c>: thesis Table 7-2 and Figures 7-3 to 7-7. Writes
/// OUT/instancing.md, its charts and the scenes' images under OUT/instancing/.
/// </summary>
public static class InstancingCommand
{
    public const string ReportName = "instancing.md", ImageFolder = "instancing";

    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var output = new Option<string?>("--output", "-o")
        {
            Description = "Folder for instancing.md and the instancing/ images (default: bench/results)",
            HelpName = "DIR",
        };
        var width = Options.Integer("--width", "Image width in pixels (default 640; 96 with --quick)", 8, Options.MaxResolution);
        var height = Options.Integer("--height", "Image height in pixels (default 480; 72 with --quick)", 8, Options.MaxResolution);
        var threads = Options.Integer("--threads", "Threads of the image renders (default 1); tests are counted and timed on one thread", 1, Options.MaxThreads, "-t");
        var repeats = Options.Integer("--repeats", "Timed replays of the recorded tests per scene and method, the fastest kept (default 5; 1 with --quick)", 1, 100);
        var quick = new Option<bool>("--quick") { Description = "A small, fast run that checks the code paths; its timings mean little" };
        var command = new Command("instancing",
            "Renders the four cylinder scenes of thesis Figure 7-3 with the five cylinder methods (U, GAU, I, TSR, RSTR) and writes the Table 7-2 report.")
        {
            output, width, height, threads, repeats, quick,
        };
        command.SetAction(parsed =>
        {
            var isQuick = parsed.GetValue(quick);
            var folder = parsed.GetValue(output) ?? Path.Combine("bench", "results");
            var run = new InstancingExperiment
            {
                Width = parsed.GetValue(width) ?? (isQuick ? 96 : 640),
                Height = parsed.GetValue(height) ?? (isQuick ? 72 : 480),
                Threads = parsed.GetValue(threads) ?? 1,
                Repeats = parsed.GetValue(repeats) ?? (isQuick ? 1 : 5),
                MemorySamples = isQuick ? 100 : 20000,
                Progress = message => stderr.WriteLine(message),
            };
            try
            {
                Run(run, folder, CommandLine(parsed), stdout);
                return Application.Ok;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                stderr.WriteLine($"raytracer: error: {e.Message}");
                return Application.Failure;
            }
        });
        return command;
    }

    /// <summary>Runs the experiment and writes the images, the charts and then the report.</summary>
    internal static void Run(InstancingExperiment run, string folder, string commandLine, TextWriter stdout)
    {
        var images = Path.Combine(folder, ImageFolder);
        Directory.CreateDirectory(images);
        var written = new HashSet<string>();
        PixelImage? reference = null;
        var results = run.Run((scene, method, image) =>
        {
            if (method == CylinderMethod.UCyl)
            {
                reference = image;
                OutputFile.Write(Path.Combine(images, scene + ".png"), ImageFile.EncodePng(image));
            }
            else if (reference is not null && InstancingExperiment.Compare(reference, image).PixelsOver > 0)
            {
                var name = InstancingReport.ImageName(scene, method);
                OutputFile.Write(Path.Combine(images, name + ".png"), ImageFile.EncodePng(image));
                written.Add(name);
            }
        });

        var scenes = results.Select(r => r.Scene).Distinct().ToList();
        var groups = scenes.Select(InstancingReport.Title).ToList();
        var methods = Enum.GetValues<CylinderMethod>();
        var labels = methods.Select(InstancingExperiment.Label).ToList();
        double[] PerScene(CylinderMethod m, Func<InstancingMeasurement, double> pick) =>
            [.. scenes.Select(s => pick(results.Single(r => r.Scene == s && r.Method == m)))];
        OutputFile.Write(Path.Combine(images, "time.png"), InstancingCharts.Grouped(
            "Total test time per scene (Figure 7-4)", "time in tube tests (ms)", groups, labels,
            [.. methods.Select(m => PerScene(m, r => r.TimeMilliseconds))]));
        OutputFile.Write(Path.Combine(images, "memory.png"), InstancingCharts.Grouped(
            "Total cylinder memory per scene (Figure 7-5)", "memory (KB)", groups, labels,
            [.. methods.Select(m => PerScene(m, r => r.TotalKilobytes))]));
        OutputFile.Write(Path.Combine(images, "gain.png"), InstancingCharts.Grouped(
            "Gain in test time (Figures 7-6, 7-7)", "gain (%)", groups, [.. InstancingReport.Gains.Select(g => g.Label)],
            [.. InstancingReport.Gains.Select(g => (double[])[.. scenes.Select(s => InstancingReport.Gain(
                results.Single(r => r.Scene == s && r.Method == g.Method), results.Single(r => r.Scene == s && r.Method == g.Baseline)))])]));

        var report = InstancingReport.Write(results, commandLine, run, ImageFolder, written);
        var path = Path.Combine(folder, ReportName);
        OutputFile.Write(path, System.Text.Encoding.UTF8.GetBytes(report));
        stdout.WriteLine($"wrote {path}");
    }

    /// <summary>The command as a user would type it again from the repository root.</summary>
    private static string CommandLine(ParseResult parsed)
    {
        var words = new List<string> { "dotnet run -c Release --project src/RayTracer.App -- experiments instancing" };
        words.AddRange(parsed.Tokens.SkipWhile(t => t.Value != "instancing").Skip(1).Select(t => t.Value));
        return string.Join(' ', words);
    }
}
