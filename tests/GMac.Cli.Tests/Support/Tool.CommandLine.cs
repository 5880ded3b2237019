using GMac.Cli.Commands;

namespace GMac.CSharp.Tests.Support;

/// <summary>The whole command line, in-process (the host's flows are in Tool.cs, shared with the host's tests).</summary>
internal static partial class Tool
{
    public static (int Exit, string Out, string Err) Run(params string[] args)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var exit = CommandLine.Run(args, output, error);
        return (exit, output.ToString(), error.ToString());
    }
}
