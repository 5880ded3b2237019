using System.CommandLine;
using System.CommandLine.Invocation;

namespace GMac.Cli.Commands;

/// <summary>
/// The <c>gmac</c> command tree and how a run maps onto the exit codes: 0 ok, 1 diagnostics,
/// 2 usage errors (anything the parser or an option's validator rejects).
/// </summary>
internal static class CommandLine
{
    public static RootCommand CreateRoot() =>
        new("gmac: generates C# from geometric-algebra macros written in GMacDSL into the #region GMac blocks of C# files.")
        {
            GenerateCommand.Create(),
            CheckCommand.Create(),
            ShowCommand.Create(),
            VerifyCommand.Create(),
            CookbookCommand.Create(),
            LspCommand.Create(),
        };

    public static int Run(IReadOnlyList<string> args, TextWriter output, TextWriter error)
    {
        // 'gmac help' stays a way to ask for the overview.
        if (args is ["help"]) args = ["--help"];
        // Paths are taken as written: a path that begins with '@' is not a response file.
        var result = CreateRoot().Parse(args, new ParserConfiguration { ResponseFileTokenReplacer = null });
        if (result.Action is ParseErrorAction usage)
        {
            // The errors, suggestions for a mistyped name, then the command's help, all on standard error.
            usage.ShowHelp = true;
            usage.ShowTypoCorrections = true;
            result.Invoke(new InvocationConfiguration { Output = error, Error = error });
            return ExitCodes.Usage;
        }
        try
        {
            return result.Invoke(new InvocationConfiguration { Output = output, Error = error, EnableDefaultExceptionHandler = false });
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // Files are only ever replaced whole, so stopping here leaves no source half-written.
            error.WriteLine($"gmac {result.CommandResult.Command.Name}: internal error: {e.GetType().Name}: {e.Message}");
            return ExitCodes.Diagnostics;
        }
    }
}
