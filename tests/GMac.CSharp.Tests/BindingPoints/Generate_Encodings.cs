using System.Text;
using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>Files in any encoding keep every byte outside their regions when a region is rewritten.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_Encodings : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    /// <summary>Generates <paramref name="bytes"/> as a file; asserts it changed only between the region's last binding line and <c>#endregion</c>.</summary>
    private void AssertOnlyTheRegionBodyChanges(byte[] bytes, Encoding encoding)
    {
        var path = Path.Combine(_temp.Path, "Normals.cs");
        File.WriteAllBytes(path, bytes);
        var bodyStart = IndexOf(bytes, encoding.GetBytes(StaleKernel.StaleLine));
        var bodyEnd = bodyStart + encoding.GetBytes(StaleKernel.StaleLine + "\n").Length;

        var (exit, _, err) = Tool.Generate([_temp.Path]);

        Assert.True(exit == 0, err);
        var after = File.ReadAllBytes(path);
        var suffixLength = bytes.Length - bodyEnd;
        Assert.Equal(bytes[..bodyStart], after[..bodyStart]);
        Assert.Equal(bytes[bodyEnd..], after[^suffixLength..]);
        var body = encoding.GetString(after[bodyStart..^suffixLength]);
        Assert.Contains(StaleKernel.GeneratedMarker, body, StringComparison.Ordinal);
        Assert.DoesNotContain("stale", body, StringComparison.Ordinal);
    }

    private static int IndexOf(byte[] haystack, byte[] needle)
    {
        var at = haystack.AsSpan().IndexOf(needle);
        Assert.True(at >= 0, "marker not found");
        return at;
    }

    [Fact]
    public void Windows_1252_comments_around_a_region_keep_every_byte()
    {
        // "Grüße, café © €" in Windows-1252: single bytes that are not valid UTF-8
        byte[] comment = [.. "// Gr"u8, 0xFC, 0xDF, .. "e, caf"u8, 0xE9, .. " "u8, 0xA9, .. " "u8, 0x80, .. "\n"u8];
        var text = Encoding.ASCII.GetBytes(StaleKernel.Text);
        var insideClass = IndexOf(text, "    public static"u8.ToArray());
        byte[] bytes = [.. comment, .. text[..insideClass], .. comment, .. text[insideClass..], .. comment];
        AssertOnlyTheRegionBodyChanges(bytes, Encoding.Latin1);
    }

    [Fact]
    public void Invalid_utf8_after_valid_utf8_keeps_every_byte()
    {
        byte[] bytes = [.. "// Grüße (UTF-8), then a stray byte: "u8, 0xC3, .. "\n"u8, .. Encoding.UTF8.GetBytes(StaleKernel.Text)];
        AssertOnlyTheRegionBodyChanges(bytes, Encoding.Latin1);
    }

    [Fact]
    public void Utf32_with_a_byte_order_mark_is_read_as_utf32()
    {
        var encoding = new UTF32Encoding(bigEndian: false, byteOrderMark: true);
        byte[] bytes = [.. encoding.GetPreamble(), .. encoding.GetBytes("// Grüße\n" + StaleKernel.Text)];
        AssertOnlyTheRegionBodyChanges(bytes, encoding);
    }

    [Fact]
    public void Utf8_with_a_byte_order_mark_keeps_it()
    {
        var encoding = new UTF8Encoding(encoderShouldEmitUTF8Identifier: true);
        byte[] bytes = [.. encoding.GetPreamble(), .. encoding.GetBytes("// Grüße, café ©\n" + StaleKernel.Text)];
        AssertOnlyTheRegionBodyChanges(bytes, encoding);
    }

    /// <summary>The kernel's bytes with <paramref name="comment"/> at the end of each bind line.</summary>
    private static byte[] WithCommentOnBindLines(byte[] comment)
    {
        var bytes = new List<byte>();
        foreach (var line in StaleKernel.Text.Split('\n'))
        {
            bytes.AddRange(Encoding.ASCII.GetBytes(line));
            if (line.Contains("//GMac.", StringComparison.Ordinal)) bytes.AddRange(comment);
            bytes.Add((byte)'\n');
        }
        return [.. bytes[..^1]];
    }

    [Fact]
    public void Byte_0x85_of_windows_1252_and_shift_jis_on_bind_lines_is_no_line_break()
    {
        // " // wait… ュ": 0x85 is '…' in Windows-1252, the second byte of 'ュ' (0x83 0x85) in Shift-JIS;
        // as Latin-1 it is U+0085, a line break for Roslyn.
        var bytes = WithCommentOnBindLines([.. " // wait"u8, 0x85, .. " "u8, 0x83, 0x85]);
        AssertOnlyTheRegionBodyChanges(bytes, Encoding.Latin1);
        Assert.Empty(CSharpCompile.Errors(Path.Combine(_temp.Path, "Normals.cs")));
    }

    [Fact]
    public void Lines_of_diagnostics_after_byte_0x85_are_the_editors()
    {
        byte[] comment = [.. "// "u8, 0x85, 0x85, 0x85, .. "\n"u8];
        var text = Encoding.ASCII.GetBytes(StaleKernel.Text.Replace("\"u.e3\", uz", "\"u.e9\", uz", StringComparison.Ordinal));
        byte[] bytes = [.. comment, .. comment, .. text];
        var path = Path.Combine(_temp.Path, "Normals.cs");
        File.WriteAllBytes(path, bytes);
        // The line as an editor counts it: line feeds before the bad blade, plus one.
        var at = IndexOf(bytes, "\"u.e9\""u8.ToArray());
        var line = bytes[..at].Count(b => b == (byte)'\n') + 1;

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains($"Normals.cs({line},", err, StringComparison.Ordinal);
        Assert.Contains("GMAC0303", err, StringComparison.Ordinal);
        Assert.Equal(bytes, File.ReadAllBytes(path));
    }

    [Fact]
    public void A_stray_byte_elsewhere_leaves_utf8_bind_lines_as_they_are()
    {
        // One byte that is not UTF-8 in a comment; the bind lines read a variable named in Greek.
        var text = StaleKernel.Text
            .Replace("double ux,", "double ψx,", StringComparison.Ordinal)
            .Replace("\"u.e1\", ux", "\"u.e1\", \"<ψx>\"", StringComparison.Ordinal);
        byte[] bytes = [.. "// a stray byte: "u8, 0xFF, .. "\n"u8, .. Encoding.UTF8.GetBytes(text)];
        AssertOnlyTheRegionBodyChanges(bytes, Encoding.UTF8);
        var after = File.ReadAllBytes(Path.Combine(_temp.Path, "Normals.cs"));
        var body = Encoding.UTF8.GetString(after[IndexOf(after, "wx = "u8.ToArray())..IndexOf(after, "#endregion"u8.ToArray())]);
        Assert.Contains("ψx", body, StringComparison.Ordinal);
    }

    [Fact]
    public void A_windows_1252_letter_in_a_bind_line_is_a_letter()
    {
        // "größe" in Windows-1252, a parameter read by a bind line.
        byte[] name = [.. "gr"u8, 0xF6, 0xDF, .. "e"u8];
        var text = Encoding.ASCII.GetBytes(StaleKernel.Text.Replace("ux", "@@", StringComparison.Ordinal));
        var bytes = new List<byte>(text);
        for (var at = bytes.IndexOf((byte)'@'); at >= 0; at = bytes.IndexOf((byte)'@'))
        {
            bytes.RemoveRange(at, 2);
            bytes.InsertRange(at, name);
        }
        AssertOnlyTheRegionBodyChanges([.. bytes], Encoding.Latin1);
        var after = File.ReadAllBytes(Path.Combine(_temp.Path, "Normals.cs"));
        Assert.True(after.AsSpan(IndexOf(after, "wx = "u8.ToArray())).IndexOf(name) >= 0);
    }

    [Fact]
    public void A_bind_line_with_a_byte_that_is_not_utf8_is_reported_with_where_the_byte_is()
    {
        // Byte 0x81 (no character in Windows-1252, the lead byte of many Shift-JIS ones) inside the C# text of a bind line.
        var text = Encoding.ASCII.GetBytes(StaleKernel.Text.Replace("\"u.e1\", ux", "\"u.e1\", \"<caf?>\"", StringComparison.Ordinal));
        var at = IndexOf(text, "caf?"u8.ToArray()) + 3;
        text[at] = 0x81;
        var path = Path.Combine(_temp.Path, "Normals.cs");
        File.WriteAllBytes(path, text);
        var line = text[..at].Count(b => b == (byte)'\n') + 1;
        var column = at - Array.LastIndexOf(text, (byte)'\n', at);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains($"not valid UTF-8: byte 0x81 at line {line}, column {column}; save the file as UTF-8", err, StringComparison.Ordinal);
        Assert.Equal(text, File.ReadAllBytes(path));
    }
}
