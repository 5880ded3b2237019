using System.CommandLine;
using System.CommandLine.Parsing;
using GMac.CSharp.BindingPoints;

namespace GMac.Cli.Commands;

/// <summary>
/// Where a command finds its GMacDSL: <c>--dsl</c> (a folder or a <c>.gmac</c> file, repeatable),
/// <c>--dsl-from</c> (a file listing such paths, one a line, as the MSBuild step writes it) and
/// <c>--standard-library</c> (the library shipped next to gmac). All of them are bound as one
/// project; at least one must be given.
/// </summary>
internal sealed class DslOptions
{
    public Option<string[]> Sources { get; } = SharedOptions.NotBlank(new Option<string[]>("--dsl")
    {
        Description = "a GMacDSL folder (all its .gmac files) or one .gmac file; repeatable",
        HelpName = "DIR|FILE",
        Arity = ArgumentArity.OneOrMore,
    }, "a folder or a .gmac file");

    public Option<string?> ListFile { get; } = SharedOptions.NotBlank(new Option<string?>("--dsl-from")
    {
        Description = "a file listing GMacDSL folders or .gmac files, one a line (relative paths from the list's folder)",
        HelpName = "FILE",
    }, "a file");

    public Option<bool> StandardLibrary { get; } = new("--standard-library")
    {
        Description = "also load the GMacDSL library shipped with gmac (frames e2d, e3d, cga5d, pga, their classes and macros)",
    };

    public void AddTo(Command command)
    {
        command.Options.Add(Sources);
        command.Options.Add(ListFile);
        command.Options.Add(StandardLibrary);
        command.Validators.Add(result =>
        {
            // A '--' token taken as a PATH or MACRO is a mistyped option, reported with a suggestion
            // by UnknownOptions; this error would hide it. GetResult, not GetValue: a bare '--dsl'
            // without a value is already the parser's error.
            if (result.Tokens.Any(t => t.Type == TokenType.Argument && t.Value.StartsWith("--", StringComparison.Ordinal))) return;
            if (result.GetResult(Sources) is null && result.GetResult(ListFile) is null && !result.GetValue(StandardLibrary))
                result.AddError("Option '--dsl' is required (or '--dsl-from', or '--standard-library'): the GMacDSL folders or .gmac files to load.");
        });
    }

    /// <summary>
    /// The folders and files to load, in the order given; null (exit code 1, with a diagnostic)
    /// when the list cannot be read.
    /// </summary>
    public IReadOnlyList<string>? Resolve(ParseResult result, TextWriter error, out int exitCode)
    {
        exitCode = ExitCodes.Success;
        var sources = new List<string>(result.GetValue(Sources) ?? []);
        if (result.GetValue(ListFile) is { } list)
        {
            if (SourceList.Read(list, error, "GMacDSL folders and files") is not { } listed)
            {
                exitCode = ExitCodes.Diagnostics;
                return null;
            }
            sources.AddRange(listed);
        }
        if (result.GetValue(StandardLibrary)) sources.Add(StandardLibraryDirectory);
        return sources;
    }

    /// <summary>Binds the sources into a generation context whose cache is <paramref name="cache"/>, else <see cref="DefaultCacheDirectory"/>; null (errors printed) when the DSL has errors.</summary>
    public static GenerationContext? Load(IReadOnlyList<string> sources, string? cache, TextWriter error) =>
        DslLoader.Load(sources, cache ?? DefaultCacheDirectory(sources), error);

    /// <summary>The library copied next to gmac's own assembly (see GMac.Cli.csproj).</summary>
    public static string StandardLibraryDirectory => Path.Combine(AppContext.BaseDirectory, "dsl");

    /// <summary>
    /// Where the simplifier's answers persist when <c>--cache</c> is not given: beside the first DSL
    /// folder or file the user named; nowhere (memory only) for the shipped library alone, whose
    /// folder may not be writable.
    /// </summary>
    public static string? DefaultCacheDirectory(IReadOnlyList<string> sources)
    {
        var first = sources.FirstOrDefault(s => !string.Equals(Path.GetFullPath(s), StandardLibraryDirectory, StringComparison.Ordinal));
        if (first is null) return null;
        var folder = File.Exists(first) ? Path.GetDirectoryName(Path.GetFullPath(first))! : first;
        return GenerationContext.DefaultCacheDirectory(folder);
    }
}
