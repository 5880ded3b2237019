using System.CommandLine;
using GMac.CSharp.Docs;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac cookbook --dsl DIR [-o FILE] [--check]</c>: writes the cookbook of the library's macros
/// (docs/cookbook.md) from the DSL and its cookbook comments; the content is built by <see cref="Cookbook"/>.
/// </summary>
internal static class CookbookCommand
{
    public static Command Create()
    {
        var output = new Option<string?>("--output", "-o")
        {
            Description = "the Markdown file to write (default: standard output)",
            HelpName = "FILE",
        };
        var check = new Option<bool>("--check") { Description = "write nothing; exit 1 if FILE differs from what would be written" };
        var cache = SharedOptions.Cache();
        var dsl = new DslOptions();
        var command = new Command("cookbook",
            "Write the cookbook of a GMacDSL library: its macros grouped by use, each with its signature, the binding point a user writes " +
            "(through the library's class bindings), the operation counts of the code generated for it, and the hand formula it matches. " +
            "Groups and the rest come from comments in the .gmac files: '// cookbook group N: Title' in a file puts its macros in that group; " +
            "above a macro, '// cookbook bind: u=Vector3D, w=Normal3D' names the class bindings shown, '// cookbook hand: TEXT' the hand formula, " +
            "'// cookbook group: Title' another file's group. The repository's docs/cookbook.md is written by " +
            "'gmac cookbook --dsl dsl -o docs/cookbook.md' (a test fails while it is out of date).")
        { output, check, cache };
        dsl.AddTo(command);
        command.Validators.Add(r =>
        {
            if (r.GetValue(check) && r.GetResult(output) is null) r.AddError("--check needs --output FILE: the file to compare");
        });
        command.SetAction(r =>
        {
            var error = r.InvocationConfiguration.Error;
            if (dsl.Resolve(r, error, out var failure) is not { } sources) return failure;
            var context = DslOptions.Load(sources, r.GetValue(cache), error);
            if (context is null) return ExitCodes.Diagnostics;
            var (markdown, problems) = Cookbook.Markdown(context, Path.GetFileName(Path.TrimEndingDirectorySeparator(sources[0])));
            foreach (var problem in problems) error.WriteLine(problem);
            if (markdown is null) return ExitCodes.Diagnostics;
            var path = r.GetValue(output);
            if (path is null)
            {
                r.InvocationConfiguration.Output.Write(markdown);
                return ExitCodes.Success;
            }
            return r.GetValue(check) ? Check(path, markdown, error) : Write(path, markdown, error);
        });
        return command;
    }

    private static int Check(string path, string markdown, TextWriter error)
    {
        var current = File.Exists(path) ? File.ReadAllText(path).ReplaceLineEndings("\n") : null;
        if (string.Equals(current, markdown, StringComparison.Ordinal)) return ExitCodes.Success;
        error.WriteLine($"{path}: error: the cookbook is {(current is null ? "missing" : "out of date")}; run '{CookbookMarkdown.Command}'");
        return ExitCodes.Diagnostics;
    }

    private static int Write(string path, string markdown, TextWriter error)
    {
        try
        {
            File.WriteAllText(path, markdown);
            return ExitCodes.Success;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"{path}: error: cannot write the cookbook: {e.Message}");
            return ExitCodes.Diagnostics;
        }
    }
}
