using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

public class PngDecoder_Formats
{
    [Fact]
    public void Reads_a_hand_built_palette_image_with_transparency()
    {
        var palette = new byte[] { 255, 0, 0, 0, 255, 0, 0, 0, 255 };
        // Two rows of three indices, filter byte 0 (None) at the start of each row.
        var scanlines = new byte[] { 0, 0, 1, 2, 0, 2, 1, 0 };
        var png = PngTestFiles.File(
            PngTestFiles.Header(3, 2, colorType: 3),
            PngTestFiles.Chunk("PLTE", palette),
            PngTestFiles.Chunk("tRNS", [128]),
            PngTestFiles.ImageData(scanlines),
            PngTestFiles.Chunk("IEND", []));
        var image = PngDecoder.Decode(png);
        Assert.Equal(4, image.Channels);
        Assert.Equal((255, 0, 0), ToInts(image.GetRgb(0, 0)));
        Assert.Equal((0, 0, 255), ToInts(image.GetRgb(2, 0)));
        Assert.Equal((0, 255, 0), ToInts(image.GetRgb(1, 1)));
        Assert.Equal(128, image[0, 0, 3]);
        Assert.Equal(255, image[1, 0, 3]);
    }

    [Fact]
    public void Reads_a_hand_built_gray_image_with_sub_and_up_filters()
    {
        // Row 0 Sub: deltas 10,10,10 -> 10,20,30. Row 1 Up: deltas 1,2,3 -> 11,22,33.
        var scanlines = new byte[] { 1, 10, 10, 10, 2, 1, 2, 3 };
        var png = PngTestFiles.File(
            PngTestFiles.Header(3, 2, colorType: 0),
            PngTestFiles.ImageData(scanlines),
            PngTestFiles.Chunk("tEXt", "Comment\0skipped"u8.ToArray()),
            PngTestFiles.Chunk("IEND", []));
        var image = PngDecoder.Decode(png);
        Assert.Equal(1, image.Channels);
        Assert.Equal(new byte[] { 10, 20, 30, 11, 22, 33 }, image.Data);
        Assert.Equal((22, 22, 22), ToInts(image.GetRgb(1, 1)));
    }

    [Fact]
    public void Rejects_a_corrupted_crc()
    {
        var png = PngEncoder.Encode(new PixelImage(2, 2, 3));
        png[20] ^= 0x01; // inside the IHDR data
        var e = Assert.Throws<PngFormatException>(() => PngDecoder.Decode(png));
        Assert.Contains("CRC", e.Message);
    }

    [Fact]
    public void Rejects_truncation_bad_signature_and_interlacing()
    {
        var png = PngEncoder.Encode(new PixelImage(2, 2, 3));
        Assert.Throws<PngFormatException>(() => PngDecoder.Decode(png.AsSpan(0, png.Length - 12)));
        Assert.Throws<PngFormatException>(() => PngDecoder.Decode("GIF89a.........."u8));
        var interlaced = PngTestFiles.File(
            PngTestFiles.Header(1, 1, colorType: 0, interlace: 1),
            PngTestFiles.ImageData([0, 0]),
            PngTestFiles.Chunk("IEND", []));
        Assert.Contains("interlaced", Assert.Throws<PngFormatException>(() => PngDecoder.Decode(interlaced)).Message);
        var sixteenBit = PngTestFiles.File(
            PngTestFiles.Header(1, 1, colorType: 0, bitDepth: 16),
            PngTestFiles.ImageData([0, 0, 0]),
            PngTestFiles.Chunk("IEND", []));
        Assert.Contains("bit depth", Assert.Throws<PngFormatException>(() => PngDecoder.Decode(sixteenBit)).Message);
    }

    [Fact]
    public void Load_reports_the_file_name()
    {
        var path = Path.Combine(Path.GetTempPath(), "not-a-png-" + Guid.NewGuid().ToString("N") + ".png");
        File.WriteAllText(path, "hello");
        try
        {
            var e = Assert.Throws<PngFormatException>(() => PngDecoder.Load(path));
            Assert.Contains(path, e.Message);
        }
        finally
        {
            File.Delete(path);
        }
    }

    private static (int, int, int) ToInts((byte R, byte G, byte B) c) => (c.R, c.G, c.B);
}
