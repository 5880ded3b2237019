using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Tests.Support;

/// <summary>
/// DSL text with the expected diagnostic position marked by «…», so a test reads
/// like the error a user sees. Yields the clean text and the marked line/column.
/// </summary>
internal sealed record MarkedSource(string Text, int Line, int Column)
{
    public static MarkedSource Parse(string marked)
    {
        var start = marked.IndexOf('«');
        var end = marked.IndexOf('»');
        if (start < 0 || end < start) throw new ArgumentException("mark the expected span with «…»");
        var text = marked.Remove(end, 1).Remove(start, 1);
        var before = marked[..start];
        var line = before.Count(c => c == '\n') + 1;
        var column = start - (before.LastIndexOf('\n') + 1) + 1;
        return new MarkedSource(text, line, column);
    }

    /// <summary>Binds the text and returns the single diagnostic with the given code, checking its position.</summary>
    /// <param name="diagnostics">What is reported of the project: by default its own diagnostics (a host adds its checks).</param>
    public static Diagnostic AssertSingle(string marked, string code, string? prelude = null, Func<DslProject, IReadOnlyList<Diagnostic>>? diagnostics = null)
    {
        var source = Parse(marked);
        var sources = new List<(string, string)> { ("test.gmac", source.Text) };
        if (prelude is not null) sources.Add(("prelude.gmac", prelude));
        var project = DslProject.FromSources(sources);
        var reported = diagnostics?.Invoke(project) ?? project.Diagnostics;
        var matching = reported.Where(d => d.Code == code).ToList();
        Assert.True(matching.Count == 1,
            $"expected one {code}, got:\n{string.Join("\n", reported)}");
        var d = matching[0];
        Assert.Equal("test.gmac", d.Span.FilePath);
        Assert.Equal((source.Line, source.Column), (d.Span.Line, d.Span.Column));
        return d;
    }
}
