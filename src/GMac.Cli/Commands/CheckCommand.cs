using System.CommandLine;
using System.Globalization;
using GMac.CSharp.Emit;
using GMac.Dsl;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac check --dsl DIR|FILE… [--timing]</c>: parses and binds a GMacDSL folder and
/// prints its diagnostics (MSBuild format) on standard error.
/// </summary>
internal static class CheckCommand
{
    public static Command Create()
    {
        var dsl = new DslOptions();
        var timing = new Option<bool>("--timing") { Description = "also print the warm parse+bind time (median of 20 runs)" };
        var command = new Command("check", "Parse and bind a GMacDSL folder and print its diagnostics.") { timing };
        dsl.AddTo(command);
        command.SetAction(r => dsl.Resolve(r, r.InvocationConfiguration.Error, out var failure) is not { } sources ? failure : Run(sources, r.GetValue(timing), r.InvocationConfiguration.Output, r.InvocationConfiguration.Error));
        return command;
    }

    private static int Run(IReadOnlyList<string> dsl, bool timing, TextWriter output, TextWriter error)
    {
        DslProject project;
        try
        {
            project = DslProject.Load(dsl);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // A defect of the checker itself: still a message and an exit code, not a stack trace.
            error.WriteLine($"gmac check: internal error while checking '{string.Join("', '", dsl)}': {e.Message}");
            return ExitCodes.Diagnostics;
        }
        var diagnostics = OutputBlockCheck.Diagnostics(project);
        foreach (var diagnostic in diagnostics) error.WriteLine(diagnostic);
        var errors = diagnostics.Count(d => d.IsError);
        var warnings = diagnostics.Count - errors;
        output.WriteLine($"{project.SyntaxTrees.Count} file(s), {project.Model.Macros.Count} macro(s): {errors} error(s), {warnings} warning(s)");
        if (timing)
        {
            var warm = DslTiming.MeasureWarm(project, repetitions: 20);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"parse+bind (warm, median of 20): {warm.TotalMilliseconds:F1} ms"));
        }
        return errors > 0 ? ExitCodes.Diagnostics : ExitCodes.Success;
    }
}
