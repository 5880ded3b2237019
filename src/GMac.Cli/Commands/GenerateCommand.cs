using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.Text;
using GMac.CSharp.BindingPoints;
using GMac.Dsl.Diagnostics;
using SafeFiles;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac generate [PATH…] [--sources-from FILE] --dsl DIR|FILE… [--dsl-from FILE] [--standard-library] [--check] [--stats] [--cache DIR] [--scalar float|double]</c>:
/// rewrites every binding point under the paths and in the listed files; with <c>--check</c> only
/// reports files that are out of date.
/// </summary>
internal static class GenerateCommand
{
    public static Command Create()
    {
        var paths = SharedOptions.Paths("C# files or folders whose binding points are rewritten");
        var sourcesFrom = new Option<string?>("--sources-from")
        {
            Description = "also rewrite the C# files listed in FILE, one path a line, relative to FILE's folder (with it, no PATH means none)",
            HelpName = "FILE",
        };
        sourcesFrom.Validators.Add(result =>
        {
            if (result.Tokens.Any(t => string.IsNullOrWhiteSpace(t.Value))) result.AddError("--sources-from needs the path of a file listing C# files");
        });
        var dsl = new DslOptions();
        var check = new Option<bool>("--check") { Description = "write nothing; exit 1 if any region is out of date" };
        var stats = SharedOptions.Stats("begin each region with a comment counting its operations");
        var cache = SharedOptions.Cache();
        var scalar = SharedOptions.Scalar("the scalar type of the code where a binding point has no //GMac.Type line (default: double)");
        var command = new Command("generate", "Rewrite the binding points (#region GMac blocks) of C# files.") { paths, sourcesFrom, check, stats, cache, scalar };
        dsl.AddTo(command);
        UnknownOptions.RejectIn(paths, command);
        command.SetAction(r =>
        {
            var watch = Stopwatch.StartNew();
            var error = r.InvocationConfiguration.Error;
            // A list stands for the files to work on (an MSBuild project's Compile items), so with
            // one the current folder is not scanned as well unless it is named.
            var sources = SharedOptions.PathsOrCurrent(r.GetValue(paths));
            if (r.GetValue(sourcesFrom) is { } list)
            {
                if (SourceList.Read(list, error) is not { } listed) return ExitCodes.Diagnostics;
                sources = [.. r.GetValue(paths) ?? [], .. listed];
            }
            if (dsl.Resolve(r, error, out var failure) is not { } dslSources) return failure;
            var context = DslLoader.Load(dslSources, r.GetValue(cache) ?? DslOptions.DefaultCacheDirectory(dslSources), error);
            if (context is null) return ExitCodes.Diagnostics;
            context.DefaultScalarType = r.GetValue(scalar)!;
            return Execute(context, sources, r.GetValue(check), r.GetValue(stats), r.InvocationConfiguration.Output, error, watch);
        });
        return command;
    }

    /// <summary>
    /// Generates with an already loaded DSL (what tests and the other commands share).
    /// <paramref name="beforeWrite"/> runs just before each file is written, so tests can edit it then.
    /// </summary>
    public static int Execute(GenerationContext context, IReadOnlyList<string> paths, bool check, bool stats, TextWriter output, TextWriter error,
        Stopwatch? watch = null, Action<string>? beforeWrite = null)
    {
        watch ??= Stopwatch.StartNew();
        var hitsBefore = context.Cas.TotalHits;
        var missesBefore = context.Cache.Misses;
        var scan = SourceScanner.Scan(paths);
        foreach (var m in scan.Problems) error.WriteLine(m);
        foreach (var s in scan.Skipped) error.WriteLine(s);
        var files = scan.Files;
        int scanned = 0, regions = 0, changed = 0, failed = scan.Problems.Count, outOfDate = 0, skipped = 0;
        // A check accepts regions with or without the statistics header, so it generates them with
        // it (the header is one line, easy to take off) and keeps its own entries in the index.
        var generateStats = stats || check;
        var index = GeneratedFileIndex.Open(context.CacheDirectory, context, check ? null : stats);
        var pending = new List<string>();
        foreach (var path in files)
        {
            scanned++;
            if (TryReadBytes(path) is { } bytes && index.IsCurrent(path, bytes))
            {
                skipped++;
                continue;
            }
            pending.Add(path);
        }
        // Files are generated on every core (the generator and its caches are shared and safe for
        // that; no region depends on another file), then reported and written one by one in the
        // order of the scan, so output and exit code do not depend on which thread finished first.
        // Each file keeps the bytes it was generated from: it is written only if it still holds them.
        var generated = new (FileGeneration? Generation, string Errors, byte[] Read)[pending.Count];
        Parallel.For(0, pending.Count, new ParallelOptions { MaxDegreeOfParallelism = Environment.ProcessorCount }, i =>
        {
            using var fileErrors = new StringWriter();
            var generation = GenerateFile(pending[i], context, generateStats, fileErrors, out var read);
            generated[i] = (generation, fileErrors.ToString(), read);
        });
        for (var i = 0; i < pending.Count; i++)
        {
            var path = pending[i];
            var (generation, fileErrors, read) = generated[i];
            generated[i] = default; // let the file's text go once it is handled
            error.Write(fileErrors);
            if (generation is null)
            {
                failed++;
                continue;
            }
            if (generation.File.Points.Count == 0 && generation.Succeeded) continue;
            if (!generation.Succeeded)
            {
                foreach (var d in generation.Diagnostics) error.WriteLine(d);
                failed++;
                continue;
            }
            regions += generation.Regions.Count;
            var first = generation.File.Points[0];
            var firstRegion = SourceSpan.At(path, first.RegionLineNumber, first.RegionColumn);
            if (!generation.Changed)
            {
                index.Record(path, read);
                continue;
            }
            if (check)
            {
                var stale = StaleRegions(generation).ToList();
                if (stale.Count == 0)
                {
                    // every region is current, some with the header and some without
                    index.Record(path, read);
                    continue;
                }
                outOfDate++;
                foreach (var r in stale)
                    error.WriteLine(new Diagnostic(DiagnosticCodes.OutOfDate, SourceSpan.At(path, r.Point.RegionLineNumber, r.Point.RegionColumn), $"binding point '{r.Point.MacroName}' is out of date; run 'gmac generate'"));
                continue;
            }
            byte[] newBytes;
            try
            {
                newBytes = generation.File.Source.Encode(generation.NewText);
            }
            catch (EncoderFallbackException e)
            {
                error.WriteLine(new Diagnostic(DiagnosticCodes.CannotWrite, firstRegion, $"cannot write the generated code in the file's encoding ({generation.File.Source.Encoding.WebName}): {e.Message}; the file is unchanged"));
                failed++;
                continue;
            }
            beforeWrite?.Invoke(path);
            if (TryReplace(path, newBytes, read) is { } why)
            {
                error.WriteLine(new Diagnostic(DiagnosticCodes.CannotWrite, firstRegion, why));
                failed++;
                continue;
            }
            changed++;
            index.Record(path, newBytes);
        }
        index.Save();
        context.Cache.Flush();
        var hits = context.Cas.TotalHits - hitsBefore;
        var misses = context.Cache.Misses - missesBefore;
        output.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"gmac generate: {scanned} file(s) scanned, {regions} region(s) generated, {skipped} file(s) unchanged since the last run, {(check ? $"{outOfDate} file(s) out of date" : $"{changed} file(s) changed")}, {failed} file(s) with errors, cache {hits} hit(s) {misses} miss(es), {watch.Elapsed.TotalMilliseconds:F0} ms"));
        return failed > 0 || outOfDate > 0 ? ExitCodes.Diagnostics : ExitCodes.Success;
    }

    /// <summary>
    /// Writes the file if it still holds the bytes it was generated from; null on success, else
    /// the message: an edit made during the run is kept, and a file deleted meanwhile stays deleted.
    /// </summary>
    private static string? TryReplace(string path, byte[] newBytes, byte[] read)
    {
        try
        {
            AtomicFile.Replace(path, newBytes, read);
            return null;
        }
        catch (FileChangedException e)
        {
            return e.Deleted
                ? "the file was deleted while gmac generated it; it is not created again"
                : "the file was changed while gmac generated it; it is left as it is now (run 'gmac generate' again to generate it)";
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return $"cannot write the generated code: {e.Message}; the file is unchanged";
        }
    }

    private static byte[]? TryReadBytes(string path)
    {
        try
        {
            return File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    /// <summary>Reads and generates one file; null (with a diagnostic) when it cannot be read.</summary>
    internal static FileGeneration? GenerateFile(string path, GenerationContext context, bool stats, TextWriter error) =>
        GenerateFile(path, context, stats, error, out _);

    /// <summary>Reads and generates one file, giving the bytes it read (empty when it could not read them).</summary>
    private static FileGeneration? GenerateFile(string path, GenerationContext context, bool stats, TextWriter error, out byte[] read)
    {
        SourceText source;
        read = [];
        try
        {
            read = File.ReadAllBytes(path);
            source = SourceText.Decode(path, read);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            error.WriteLine(new Diagnostic(DiagnosticCodes.CannotReadSource, SourceSpan.None(path), $"cannot read file: {e.Message}"));
            return null;
        }
        var file = BindingPointReader.MayContainBindingPoints(source.Text)
            ? BindingPointReader.Read(source)
            : new BindingPointFile(source, [], [], [], new HashSet<string>());
        return BindingPointGenerator.Generate(file, context, stats);
    }

    /// <summary>
    /// The regions that differ from what generation writes: their <c>//GMac.</c> lines first, then
    /// the code, with or without its statistics header (<paramref name="generation"/> has it).
    /// </summary>
    private static IEnumerable<GeneratedRegion> StaleRegions(FileGeneration generation)
    {
        var lines = generation.File.Lines;
        return generation.Regions.Where(r =>
        {
            var inside = Enumerable.Range(r.Point.RegionLine + 1, r.Point.EndRegionLine - r.Point.RegionLine - 1).Select(i => lines[i]).ToList();
            var text = string.Concat(inside);
            var bindings = string.Concat(inside.Where(BindingLineReader.IsBindingLine));
            var code = r.Code ?? "";
            return !string.Equals(text, bindings + code, StringComparison.Ordinal)
                && !string.Equals(text, bindings + WithoutStatistics(code), StringComparison.Ordinal);
        }).ToList();
    }

    /// <summary>The emitted code without its first line, the statistics header (ended by "\n", "\r\n" or "\r", as the file's lines are).</summary>
    private static string WithoutStatistics(string code)
    {
        var end = code.AsSpan().IndexOfAny('\r', '\n');
        if (end >= 0 && code[end] == '\r' && end + 1 < code.Length && code[end + 1] == '\n') end++;
        return end >= 0 && code.TrimStart().StartsWith(StatisticsHeader, StringComparison.Ordinal) ? code[(end + 1)..] : code;
    }

    /// <summary>How the emitter begins the statistics line.</summary>
    private const string StatisticsHeader = "// GMac: ";
}
