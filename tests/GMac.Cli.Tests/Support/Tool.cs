using GMac.Cli.BindingPoints;
using GMac.Cli.Commands;

namespace GMac.Cli.Tests.Support;

/// <summary>Runs commands in-process and captures their output and errors.</summary>
internal static class Tool
{
    /// <summary><paramref name="beforeWrite"/> runs just before each file is written (to edit it during the run).</summary>
    public static (int Exit, string Out, string Err) Generate(IReadOnlyList<string> paths, bool check = false, bool stats = false, GenerationContext? context = null,
        Action<string>? beforeWrite = null)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var exit = GenerateCommand.Execute(context ?? SharedDsl.Context, paths, check, stats, output, error, beforeWrite: beforeWrite);
        return (exit, output.ToString(), error.ToString());
    }

    public static (int Exit, string Out, string Err) Verify(params string[] paths)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var exit = VerifyCommand.Execute(SharedDsl.Context, paths, seed: 1, output, error);
        return (exit, output.ToString(), error.ToString());
    }

    public static (int Exit, string Out, string Err) Run(params string[] args)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var exit = CommandLine.Run(args, output, error);
        return (exit, output.ToString(), error.ToString());
    }
}
