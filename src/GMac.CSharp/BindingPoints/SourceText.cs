using System.Text;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// A C# file as read from disk: its text, the encoding (and whether it had a byte-order mark) and
/// its line ending, so that a rewrite reproduces every byte it does not mean to change.
/// </summary>
internal sealed class SourceText
{
    private static readonly UTF8Encoding StrictUtf8 = new(false, true);

    // Latin-1 maps each byte to the character of the same number and back, so a file in any
    // single-byte code page (Windows-1252, ISO-8859-x) survives a rewrite byte for byte, and its
    // letters are letters to the C# parser. Byte 0x85 (Windows-1252 '…') becomes U+0085, a line
    // break for Roslyn but not for editors: see ForParsing.
    private static readonly Encoding ByteForByte = Encoding.GetEncoding("iso-8859-1", EncoderFallback.ExceptionFallback, DecoderFallback.ExceptionFallback);

    // A UTF-8 file with a few invalid bytes (a stray byte in a string) is not read as Latin-1, which
    // would garble its valid UTF-8 (a 'ψ' on a bind line): each invalid byte becomes the lone low
    // surrogate U+DC00 + byte (Python's "surrogateescape"), which valid UTF-8 cannot give, and is
    // written back as that byte.
    private const char FirstEscapedByte = '\uDC80';
    private const char LastEscapedByte = '\uDCFF';

    private enum Fallback { None, Latin1, EscapedBytes }

    private readonly Fallback _fallback;
    private readonly byte[] _preamble;

    private SourceText(string path, string text, Encoding encoding, byte[] preamble, Fallback fallback)
    {
        Path = path;
        Text = text;
        Encoding = encoding;
        _preamble = preamble;
        _fallback = fallback;
        NewLine = FirstLineBreak(text);
    }

    public string Path { get; }
    public string Text { get; }
    public Encoding Encoding { get; }

    /// <summary>The file's first line ending: "\r\n", "\r" or "\n" ("\n" when it has none).</summary>
    public string NewLine { get; }

    /// <summary>Whether the file is not valid in the encoding its byte-order mark names (UTF-8 without one).</summary>
    public bool HasInvalidBytes => _fallback != Fallback.None;

    public static SourceText Read(string path) => Decode(path, File.ReadAllBytes(path));

    /// <summary>
    /// Decodes strictly with the encoding its byte-order mark names (UTF-8 without one). Bytes not
    /// valid in it are read as Latin-1 when no multi-byte UTF-8 character is among them (a file in a
    /// single-byte code page), else as UTF-8 keeping each invalid byte as it is.
    /// </summary>
    public static SourceText Decode(string path, byte[] bytes)
    {
        var (encoding, skip) = DetectEncoding(bytes);
        try
        {
            return new SourceText(path, encoding.GetString(bytes, skip, bytes.Length - skip), encoding, encoding.GetPreamble(), Fallback.None);
        }
        catch (DecoderFallbackException)
        {
            // A UTF-8 mark stays a mark; after any other mark the bytes are not what it says, so all are kept.
            var utf8Mark = encoding is UTF8Encoding && skip == 3;
            var body = bytes.AsSpan(utf8Mark ? 3 : 0);
            byte[] preamble = utf8Mark ? bytes[..3] : [];
            return HasMultiByteUtf8(body)
                ? new SourceText(path, DecodeEscapingInvalidBytes(body), StrictUtf8, preamble, Fallback.EscapedBytes)
                : new SourceText(path, ByteForByte.GetString(body), ByteForByte, preamble, Fallback.Latin1);
        }
    }

    public static SourceText FromString(string path, string text) => new(path, text, StrictUtf8, [], Fallback.None);

    /// <summary>The bytes of <paramref name="text"/> in this file's encoding, with its byte-order mark if it had one.</summary>
    /// <exception cref="EncoderFallbackException">The text has a character the encoding cannot hold.</exception>
    public byte[] Encode(string text)
    {
        using var bytes = new MemoryStream(text.Length + _preamble.Length + 16);
        bytes.Write(_preamble);
        if (_fallback != Fallback.EscapedBytes)
        {
            bytes.Write(Encoding.GetBytes(text));
            return bytes.ToArray();
        }
        var run = 0;
        for (var i = 0; i < text.Length; i++)
        {
            if (!IsEscapedByte(text, i)) continue;
            bytes.Write(StrictUtf8.GetBytes(text, run, i - run));
            bytes.WriteByte((byte)(text[i] - 0xDC00));
            run = i + 1;
        }
        bytes.Write(StrictUtf8.GetBytes(text, run, text.Length - run));
        return bytes.ToArray();
    }

    /// <summary>
    /// The first byte of <paramref name="line"/> (a line of this file) that was not valid UTF-8, with
    /// its 0-based index in the line; null when the line has none.
    /// </summary>
    public (byte Byte, int Index)? FirstInvalidByte(string line)
    {
        for (var i = 0; i < line.Length; i++)
        {
            if (_fallback == Fallback.EscapedBytes && IsEscapedByte(line, i)) return ((byte)(line[i] - 0xDC00), i);
            if (_fallback == Fallback.Latin1 && line[i] >= '\u0080') return ((byte)line[i], i);
        }
        return null;
    }

    /// <summary>
    /// The text as the compiler is given it to find directives and lines: U+0085, U+2028 and
    /// U+2029, which Roslyn takes as line breaks but editors (and this tool's line numbers) do not,
    /// become spaces. Positions stay the same, so Roslyn's lines are the lines split at CR, LF and CRLF.
    /// </summary>
    public static string ForParsing(string text) =>
        text.AsSpan().IndexOfAny('\u0085', '\u2028', '\u2029') < 0
            ? text
            : string.Create(text.Length, text, static (span, t) =>
            {
                t.AsSpan().CopyTo(span);
                foreach (ref var c in span)
                    if (c is '\u0085' or '\u2028' or '\u2029') c = ' ';
            });

    /// <summary>
    /// Lines with their own terminators, split only at CR, LF and CRLF (as editors and
    /// <see cref="ForParsing"/> split them); joining them gives the text back.
    /// </summary>
    public static List<string> SplitLines(string text)
    {
        var lines = new List<string>();
        var start = 0;
        for (var i = 0; i < text.Length; i++)
        {
            if (text[i] is not ('\r' or '\n')) continue;
            if (text[i] == '\r' && i + 1 < text.Length && text[i + 1] == '\n') i++;
            lines.Add(text[start..(i + 1)]);
            start = i + 1;
        }
        lines.Add(text[start..]);
        return lines;
    }

    /// <summary>The line ending a line ends with ("" for the last line of a file without a final one).</summary>
    public static string LineEndingOf(string line) =>
        line.EndsWith("\r\n", StringComparison.Ordinal) ? "\r\n"
        : line.EndsWith('\n') ? "\n"
        : line.EndsWith('\r') ? "\r"
        : "";

    private static bool IsEscapedByte(string text, int i) =>
        text[i] is >= FirstEscapedByte and <= LastEscapedByte && (i == 0 || !char.IsHighSurrogate(text[i - 1]));

    /// <summary>Whether the bytes hold a valid UTF-8 sequence of two bytes or more.</summary>
    private static bool HasMultiByteUtf8(ReadOnlySpan<byte> bytes)
    {
        while (bytes.IndexOfAnyExceptInRange((byte)0, (byte)0x7F) is var next and >= 0)
        {
            bytes = bytes[next..];
            if (System.Text.Rune.DecodeFromUtf8(bytes, out _, out var consumed) == System.Buffers.OperationStatus.Done) return true;
            bytes = bytes[1..];
        }
        return false;
    }

    private static string DecodeEscapingInvalidBytes(ReadOnlySpan<byte> bytes)
    {
        var text = new StringBuilder(bytes.Length);
        Span<char> chars = stackalloc char[2];
        while (!bytes.IsEmpty)
        {
            if (System.Text.Rune.DecodeFromUtf8(bytes, out var rune, out var consumed) == System.Buffers.OperationStatus.Done)
            {
                text.Append(chars[..rune.EncodeToUtf16(chars)]);
            }
            else
            {
                text.Append((char)(0xDC00 + bytes[0]));
                consumed = 1;
            }
            bytes = bytes[consumed..];
        }
        return text.ToString();
    }

    private static string FirstLineBreak(string text)
    {
        var at = text.AsSpan().IndexOfAny('\r', '\n');
        return at < 0 || text[at] == '\n' ? "\n"
            : at + 1 < text.Length && text[at + 1] == '\n' ? "\r\n"
            : "\r";
    }

    private static (Encoding Encoding, int Skip) DetectEncoding(byte[] b)
    {
        // UTF-32 LE first: its mark begins with the UTF-16 LE one.
        if (b.Length >= 4 && b[0] == 0xFF && b[1] == 0xFE && b[2] == 0 && b[3] == 0) return (new UTF32Encoding(false, true, true), 4);
        if (b.Length >= 4 && b[0] == 0 && b[1] == 0 && b[2] == 0xFE && b[3] == 0xFF) return (new UTF32Encoding(true, true, true), 4);
        if (b.Length >= 3 && b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF) return (new UTF8Encoding(true, true), 3);
        if (b.Length >= 2 && b[0] == 0xFF && b[1] == 0xFE) return (new UnicodeEncoding(false, true, true), 2);
        if (b.Length >= 2 && b[0] == 0xFE && b[1] == 0xFF) return (new UnicodeEncoding(true, true, true), 2);
        return (StrictUtf8, 0);
    }
}
