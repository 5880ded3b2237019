using System.Text;
using GMac.Cli.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

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
}
