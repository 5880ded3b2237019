namespace GMac.Cli.Commands;

/// <summary>The table of commands and the top-level help.</summary>
internal static class CommandLine
{
    private static readonly ICommand[] Commands = [new GenerateCommand(), new CheckCommand(), new ShowCommand(), new VerifyCommand()];

    public static int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        if (args.Count == 0)
        {
            PrintHelp(error);
            return ExitCodes.Usage;
        }
        if (args[0] is "--help" or "-h" or "help")
        {
            PrintHelp(output);
            return ExitCodes.Success;
        }
        var command = Commands.FirstOrDefault(c => c.Name == args[0]);
        if (command is null)
        {
            error.WriteLine($"gmac: unknown command '{args[0]}'");
            PrintHelp(error);
            return ExitCodes.Usage;
        }
        if (args.Skip(1).Any(a => a is "--help" or "-h"))
        {
            output.WriteLine($"usage: {command.Usage}");
            return ExitCodes.Success;
        }
        try
        {
            return command.Run(args.Skip(1).ToList(), output, error);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // Files are only ever replaced whole, so stopping here leaves no source half-written.
            error.WriteLine($"gmac {command.Name}: internal error: {e.GetType().Name}: {e.Message}");
            return ExitCodes.Diagnostics;
        }
    }

    private static void PrintHelp(TextWriter writer)
    {
        writer.WriteLine("usage: gmac <command> [options]");
        writer.WriteLine();
        writer.WriteLine("commands:");
        foreach (var c in Commands) writer.WriteLine($"  {c.Name,-10} {c.Summary}");
        writer.WriteLine();
        writer.WriteLine("Run 'gmac <command> --help' for the options of one command.");
    }
}
