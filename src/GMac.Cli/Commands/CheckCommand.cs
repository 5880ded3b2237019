using System.Globalization;
using GMac.Dsl;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac check --dsl DIR [--timing]</c>: parses and binds a GMacDSL folder and
/// prints its diagnostics (MSBuild format) on standard error.
/// </summary>
internal sealed class CheckCommand : ICommand
{
    public string Name => "check";
    public string Summary => "parse and bind a GMacDSL folder, print diagnostics";
    public string Usage => "gmac check --dsl DIR [--timing]";

    public int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        string? dsl = null;
        var timing = false;
        for (var i = 0; i < args.Count; i++)
        {
            switch (args[i])
            {
                case "--dsl" when i + 1 < args.Count:
                    dsl = args[++i];
                    break;
                case "--timing":
                    timing = true;
                    break;
                default:
                    error.WriteLine($"gmac check: unexpected argument '{args[i]}'");
                    error.WriteLine($"usage: {Usage}");
                    return ExitCodes.Usage;
            }
        }
        if (dsl is null)
        {
            error.WriteLine("gmac check: missing --dsl DIR");
            error.WriteLine($"usage: {Usage}");
            return ExitCodes.Usage;
        }

        DslProject project;
        try
        {
            project = DslProject.Load(dsl);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // A defect of the checker itself: still a message and an exit code, not a stack trace.
            error.WriteLine($"gmac check: internal error while checking '{dsl}': {e.Message}");
            return ExitCodes.Diagnostics;
        }
        foreach (var diagnostic in project.Diagnostics) error.WriteLine(diagnostic);
        var errors = project.Diagnostics.Count(d => d.IsError);
        var warnings = project.Diagnostics.Count - errors;
        output.WriteLine($"{project.SyntaxTrees.Count} file(s), {project.Model.Macros.Count} macro(s): {errors} error(s), {warnings} warning(s)");
        if (timing)
        {
            var warm = DslTiming.MeasureWarm(dsl, repetitions: 20);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"parse+bind (warm, median of 20): {warm.TotalMilliseconds:F1} ms"));
        }
        return errors > 0 ? ExitCodes.Diagnostics : ExitCodes.Success;
    }
}
