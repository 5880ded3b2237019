namespace GMac.Cli.LanguageServer;

/// <summary>
/// One document's text with its line starts and identifier tokens: LSP positions are 0-based
/// lines and UTF-16 columns, the DSL's 1-based lines and columns count the same characters.
/// </summary>
internal sealed class SourceText
{
    private readonly List<int> _lineStarts = [0];

    public SourceText(string path, string text)
    {
        Path = path;
        Text = text;
        for (var i = 0; i < text.Length; i++)
            if (text[i] == '\n') _lineStarts.Add(i + 1);
        Identifiers = ScanIdentifiers(text);
    }

    public string Path { get; }
    public string Text { get; }

    /// <summary>Every identifier outside comments, in order (offset, length).</summary>
    public IReadOnlyList<(int Start, int Length)> Identifiers { get; }

    public Position PositionOf(int offset)
    {
        offset = Math.Clamp(offset, 0, Text.Length);
        var line = _lineStarts.BinarySearch(offset);
        if (line < 0) line = ~line - 1;
        return new Position(line, offset - _lineStarts[line]);
    }

    public int OffsetOf(Position position)
    {
        if (position.Line < 0) return 0;
        if (position.Line >= _lineStarts.Count) return Text.Length;
        var lineEnd = position.Line + 1 < _lineStarts.Count ? _lineStarts[position.Line + 1] - 1 : Text.Length;
        return Math.Clamp(_lineStarts[position.Line] + position.Character, _lineStarts[position.Line], lineEnd);
    }

    /// <summary>The offset of a 1-based line and column, clamped into the text.</summary>
    public int OffsetOf(int line, int column) => OffsetOf(new Position(Math.Max(line - 1, 0), Math.Max(column - 1, 0)));

    public Range RangeOf(int start, int length) => new(PositionOf(start), PositionOf(start + length));

    /// <summary>The identifier under or just before <paramref name="offset"/> (the cursor may sit at its end).</summary>
    public (int Start, int Length)? IdentifierAt(int offset)
    {
        foreach (var id in Identifiers)
        {
            if (id.Start > offset) break;
            if (offset <= id.Start + id.Length) return id;
        }
        return null;
    }

    /// <summary>The length of the token at <paramref name="offset"/>: a word, or one character.</summary>
    public int TokenLengthAt(int offset)
    {
        if (offset >= Text.Length) return 0;
        var end = offset;
        while (end < Text.Length && IsIdentifierPart(Text[end])) end++;
        return end > offset ? end - offset : 1;
    }

    public string this[(int Start, int Length) token] => Text.Substring(token.Start, token.Length);

    /// <summary>The identifier right before a '.' that precedes <paramref name="start"/> (the frame of <c>e3d.Vector</c>).</summary>
    public (int Start, int Length)? QualifierOf(int start)
    {
        var i = start - 1;
        while (i >= 0 && Text[i] is ' ' or '\t') i--;
        if (i < 0 || Text[i] != '.') return null;
        i--;
        while (i >= 0 && Text[i] is ' ' or '\t') i--;
        var end = i + 1;
        while (i >= 0 && IsIdentifierPart(Text[i])) i--;
        return end > i + 1 && IsIdentifierStart(Text[i + 1]) ? (i + 1, end - i - 1) : null;
    }

    public static bool IsIdentifierStart(char c) => char.IsAsciiLetter(c) || c == '_';
    public static bool IsIdentifierPart(char c) => char.IsAsciiLetterOrDigit(c) || c == '_';

    private static List<(int, int)> ScanIdentifiers(string text)
    {
        var ids = new List<(int, int)>();
        var i = 0;
        while (i < text.Length)
        {
            var c = text[i];
            if (c == '/' && i + 1 < text.Length && text[i + 1] == '/')
            {
                while (i < text.Length && text[i] != '\n') i++;
            }
            else if (c == '/' && i + 1 < text.Length && text[i + 1] == '*')
            {
                // As the lexer: a block comment ends at the first "*/" (no nesting).
                var end = text.IndexOf("*/", i + 2, StringComparison.Ordinal);
                i = end < 0 ? text.Length : end + 2;
            }
            else if (char.IsAsciiDigit(c))
            {
                // A number, with its exponent, is not an identifier ("1e5").
                while (i < text.Length && (IsIdentifierPart(text[i]) || text[i] == '.')) i++;
            }
            else if (IsIdentifierStart(c))
            {
                var start = i;
                while (i < text.Length && IsIdentifierPart(text[i])) i++;
                ids.Add((start, i - start));
            }
            else i++;
        }
        return ids;
    }
}
