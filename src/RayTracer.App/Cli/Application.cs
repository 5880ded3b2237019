using System.CommandLine;
using System.CommandLine.Invocation;
using System.Globalization;
using RayTracer.Factories;

namespace RayTracer.Cli;

/// <summary>
/// The <c>raytracer</c> command line: list, render and bench, with generated help on every command.
/// Exit codes: 0 ok, 1 failure (a bad scene, mesh or image file, a failed render or write), 2 usage.
/// </summary>
public static class Application
{
    public const int Ok = 0, Failure = 1, Usage = 2;

    public static int Run(string[] args, TextWriter stdout, TextWriter stderr, bool interactiveProgress = false)
    {
        // 'raytracer help [COMMAND]' as people type it, besides the generated --help.
        if (args is ["help", .. var rest])
            args = [.. rest, "--help"];

        var root = CreateRootCommand(stdout, stderr, interactiveProgress);
        var parsed = root.Parse(args);
        var invocation = new InvocationConfiguration { Output = stdout, Error = stderr };
        if (parsed.Errors.Count == 0)
            return parsed.Invoke(invocation);

        ReportParseErrors(parsed, stderr);
        return Usage;
    }

    public static RootCommand CreateRootCommand(TextWriter stdout, TextWriter stderr, bool interactiveProgress) =>
        new("Renders the built-in scenes or a mesh file to PNG or HDR, and measures ray throughput.")
        {
            ListCommand(stdout),
            RenderCommand.Create(stdout, stderr, interactiveProgress),
            BenchCommand.Create(stdout, stderr),
            SnapshotCommand.Create(stdout, stderr),
            Experiments.ExperimentsCommand.Create(stdout, stderr),
        };

    /// <summary>
    /// Writes the parser's messages, each as a <c>raytracer: error:</c> line, followed by its suggestions for
    /// misspelt names and a pointer to the command's help.
    /// </summary>
    private static void ReportParseErrors(ParseResult parsed, TextWriter stderr)
    {
        var messages = parsed.Errors.Select(e => e.Message).ToHashSet(StringComparer.Ordinal);
        var details = new StringWriter();
        if (parsed.Action is ParseErrorAction action)
        {
            action.ShowHelp = false;
            action.ShowTypoCorrections = true;
            parsed.Invoke(new InvocationConfiguration { Output = details, Error = details });
        }
        else
        {
            foreach (var message in messages)
                details.WriteLine(message);
        }

        var lines = details.ToString().Split('\n', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        foreach (var line in lines.Where(messages.Contains))
            stderr.WriteLine($"raytracer: error: {line}");
        foreach (var line in lines.Where(l => !messages.Contains(l)))
            stderr.WriteLine(line);

        var command = string.Join(' ', parsed.CommandResult.Command is RootCommand ? ["raytracer"] : new[] { "raytracer", parsed.CommandResult.Command.Name });
        stderr.WriteLine($"Run '{command} --help' for usage.");
    }

    private static Command ListCommand(TextWriter stdout)
    {
        var list = new Command("list", "Lists the built-in scenes with their default size, samples and a description, then the cameras.");
        list.SetAction(_ =>
        {
            var scenes = SceneFactory.All;
            var width = scenes.Max(s => s.Name.Length);
            foreach (var scene in scenes)
                stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                    $"{scene.Name.PadRight(width)}  {scene.DefaultWidth}x{scene.DefaultHeight} {scene.DefaultSamples,3} spp  {scene.Description}"));
            stdout.WriteLine();
            stdout.WriteLine("Cameras for 'render --camera NAME[:DEGREES]' (horizontal field of view; default in brackets):");
            var nameWidth = CameraCatalog.All.Max(c => c.Name.Length);
            foreach (var camera in CameraCatalog.All)
                stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                    $"{camera.Name.PadRight(nameWidth)}  [{camera.DefaultDegrees}°, {camera.RangeText}]  {camera.Description}"));
            return Ok;
        });
        return list;
    }
}
