namespace GMac.Dsl.Diagnostics;

/// <summary>
/// A stretch of a source file: 1-based line and column of its first character,
/// plus the 0-based character offset and length for tools that underline text.
/// </summary>
public readonly record struct SourceSpan(string FilePath, int Line, int Column, int Start, int Length)
{
    public static SourceSpan None(string filePath) => new(filePath, 1, 1, 0, 0);

    /// <summary>A position known only by line and column, such as a line of a C# file.</summary>
    public static SourceSpan At(string filePath, int line, int column) => new(filePath, line, column, 0, 0);

    /// <summary>Where <paramref name="offset"/> of <paramref name="text"/> lies, when the text begins here (one character long).</summary>
    public SourceSpan Offset(string text, int offset)
    {
        var before = text.AsSpan(0, Math.Min(offset, text.Length));
        var lineBreaks = before.Count('\n');
        var lastBreak = before.LastIndexOf('\n');
        var column = lastBreak < 0 ? Column + offset : offset - lastBreak;
        return new SourceSpan(FilePath, Line + lineBreaks, column, Start + offset, 1);
    }
}
