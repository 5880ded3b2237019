using System.Diagnostics;
using System.Globalization;
using System.Text;
using GMac.Dsl.Diagnostics;
using SafeFiles;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// The flow of <c>gmac generate</c> over C# sources: scan, skip files unchanged since the last
/// run, generate each file (in parallel), then check or write them one by one in scan order.
/// </summary>
internal static class SourceGeneration
{
    /// <summary>
    /// Generates with an already loaded DSL; false when a file failed or (with <paramref name="check"/>) is out of date.
    /// <paramref name="beforeWrite"/> runs just before each file is written, so tests can edit it then.
    /// </summary>
    public static bool Run(GenerationContext context, IReadOnlyList<string> paths, bool check, bool stats, TextWriter output, TextWriter error,
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
        return failed == 0 && outOfDate == 0;
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
            : new BindingPointFile(source, [], [], [], new HashSet<string>(), new HashSet<string>());
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
