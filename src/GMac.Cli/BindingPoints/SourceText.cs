using System.Text;

namespace GMac.Cli.BindingPoints;

/// <summary>
/// A C# file as read from disk: its text, the encoding (and whether it had a byte-order mark) and
/// its line ending, so that a rewrite reproduces every byte it does not mean to change.
/// </summary>
internal sealed class SourceText
{
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

    public static SourceText Read(string path)
    {
        var bytes = File.ReadAllBytes(path);
        var (encoding, skip) = DetectEncoding(bytes);
        var text = encoding.GetString(bytes, skip, bytes.Length - skip);
        var lf = text.IndexOf('\n');
        var newLine = lf > 0 && text[lf - 1] == '\r' ? "\r\n" : "\n";
        return new SourceText(path, text, encoding, newLine);
    }

    public static SourceText FromString(string path, string text, string newLine = "\n") =>
        new(path, text, new UTF8Encoding(false), newLine);

    /// <summary>The bytes of <paramref name="text"/> in this file's encoding, with its byte-order mark if it had one.</summary>
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
        if (b.Length >= 3 && b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF) return (new UTF8Encoding(true), 3);
        if (b.Length >= 2 && b[0] == 0xFF && b[1] == 0xFE) return (new UnicodeEncoding(false, true), 2);
        if (b.Length >= 2 && b[0] == 0xFE && b[1] == 0xFF) return (new UnicodeEncoding(true, true), 2);
        return (new UTF8Encoding(false), 0);
    }
}
