using System.CommandLine;

namespace RayTracer.Cli.Experiments;

/// <summary>
/// <c>raytracer experiments NAME</c>: reproducible comparisons of intersection methods, each writing a
/// Markdown report with charts and images. Each experiment is a subcommand of its own.
/// </summary>
public static class ExperimentsCommand
{
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var experiments = new Command("experiments", "Runs the intersection-method experiments and writes their reports.");
        experiments.Subcommands.Add(InstancingCommand.Create(stdout, stderr));
        experiments.Subcommands.Add(TrianglesCommand.Create(stdout, stderr));
        return experiments;
    }
}
