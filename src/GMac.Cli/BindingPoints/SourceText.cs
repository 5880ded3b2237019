using System.Text;

namespace GMac.Cli.BindingPoints;

/// <summary>
/// A C# file as read from disk: its text, the encoding (and whether it had a byte-order mark) and
/// its line ending, so that a rewrite reproduces every byte it does not mean to change.
/// </summary>
internal sealed class SourceText
{
    // Latin-1 maps each byte to the character of the same number and back, so a file in any
    // single-byte code page (Windows-1252, ISO-8859-x) or with invalid UTF-8 survives a rewrite
    // byte for byte; the generated code is ASCII.
    private static readonly Encoding ByteForByte = Encoding.GetEncoding("iso-8859-1", EncoderFallback.ExceptionFallback, DecoderFallback.ExceptionFallback);

    private SourceText(string path, string text, Encoding encoding, string newLine)
    {
        Path = path;
        Text = text;
        Encoding = encoding;
        NewLine = newLine;
    }

    public string Path { get; }
    public string Text { get; }
    public Encoding Encoding { get; }

    /// <summary>The file's first line ending ("\n" when it has none).</summary>
    public string NewLine { get; }

    public static SourceText Read(string path) => Decode(path, File.ReadAllBytes(path));

    /// <summary>
    /// Decodes strictly with the encoding its byte-order mark names (UTF-8 without one); when the
    /// bytes are not valid in it, reads them one byte per character instead.
    /// </summary>
    public static SourceText Decode(string path, byte[] bytes)
    {
        var (encoding, skip) = DetectEncoding(bytes);
        string text;
        try
        {
            text = encoding.GetString(bytes, skip, bytes.Length - skip);
        }
        catch (DecoderFallbackException)
        {
            encoding = ByteForByte;
            text = encoding.GetString(bytes);
        }
        var lf = text.IndexOf('\n');
        var newLine = lf > 0 && text[lf - 1] == '\r' ? "\r\n" : "\n";
        return new SourceText(path, text, encoding, newLine);
    }

    public static SourceText FromString(string path, string text, string newLine = "\n") =>
        new(path, text, new UTF8Encoding(false, true), newLine);

    /// <summary>The bytes of <paramref name="text"/> in this file's encoding, with its byte-order mark if it had one.</summary>
    /// <exception cref="EncoderFallbackException">The text has a character the encoding cannot hold.</exception>
    public byte[] Encode(string text)
    {
        var preamble = Encoding.GetPreamble();
        var body = Encoding.GetBytes(text);
        var bytes = new byte[preamble.Length + body.Length];
        preamble.CopyTo(bytes, 0);
        body.CopyTo(bytes, preamble.Length);
        return bytes;
    }

    private static (Encoding Encoding, int Skip) DetectEncoding(byte[] b)
    {
        // UTF-32 LE first: its mark begins with the UTF-16 LE one.
        if (b.Length >= 4 && b[0] == 0xFF && b[1] == 0xFE && b[2] == 0 && b[3] == 0) return (new UTF32Encoding(false, true, true), 4);
        if (b.Length >= 4 && b[0] == 0 && b[1] == 0 && b[2] == 0xFE && b[3] == 0xFF) return (new UTF32Encoding(true, true, true), 4);
        if (b.Length >= 3 && b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF) return (new UTF8Encoding(true, true), 3);
        if (b.Length >= 2 && b[0] == 0xFF && b[1] == 0xFE) return (new UnicodeEncoding(false, true, true), 2);
        if (b.Length >= 2 && b[0] == 0xFE && b[1] == 0xFF) return (new UnicodeEncoding(true, true, true), 2);
        return (new UTF8Encoding(false, true), 0);
    }
}
