using GMac.Cli.Commands;

namespace GMac.Cli;

/// <summary><c>gmac &lt;command&gt; …</c>: dispatches to one command; usage errors exit 2.</summary>
internal static class Program
{
    private static int Main(string[] args) => CommandLine.Run(args, Console.Out, Console.Error);
}
