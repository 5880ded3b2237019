using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

/// <summary>PNG files built byte by byte in the tests, so the expected pixels come from how each file was made.</summary>
public class ImageFile_PngVariants
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
        var image = ImageFile.DecodePixels(png, "palette.png");
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
        var image = ImageFile.DecodePixels(png, "gray.png");
        Assert.Equal([(10, 10, 10), (20, 20, 20), (30, 30, 30), (11, 11, 11), (22, 22, 22), (33, 33, 33)],
            Enumerable.Range(0, 6).Select(i => ToInts(image.GetRgb(i % 3, i / 3))));
    }

    [Fact]
    public void Reads_a_16_bit_rgb_image_as_linear_values()
    {
        const int width = 3, height = 2;
        ushort Sample(int x, int y, int c) => (ushort)((x * 21_011 + y * 7_919 + c * 12_345) % 65_536);
        var scanlines = new List<byte>();
        for (var y = 0; y < height; y++)
        {
            scanlines.Add(0);
            for (var x = 0; x < width; x++)
            for (var c = 0; c < 3; c++)
                scanlines.AddRange([(byte)(Sample(x, y, c) >> 8), (byte)Sample(x, y, c)]);
        }
        var png = PngTestFiles.File(
            PngTestFiles.Header(width, height, colorType: 2, bitDepth: 16),
            PngTestFiles.ImageData([.. scanlines]),
            PngTestFiles.Chunk("IEND", []));

        var image = ImageFile.DecodeRadiance(png, "deep.png", gamma: 1.0);

        Assert.Equal((width, height), (image.Width, image.Height));
        for (var y = 0; y < height; y++)
        for (var x = 0; x < width; x++)
        {
            var (r, g, b) = image[x, y];
            float[] read = [r, g, b];
            for (var c = 0; c < 3; c++)
                Assert.InRange(read[c], Sample(x, y, c) / 65535.0 - 1.0 / 255, Sample(x, y, c) / 65535.0 + 1.0 / 255);
        }
    }

    [Fact]
    public void Reads_an_adam7_interlaced_image_exactly()
    {
        // 11 x 9 leaves every pass partly filled, and the last column and row fall in different passes.
        const int width = 11, height = 9;
        var pixels = new byte[width * height * 3];
        for (var i = 0; i < pixels.Length; i++)
            pixels[i] = (byte)(i * 37 % 251);
        var png = PngTestFiles.File(
            PngTestFiles.Header(width, height, colorType: 2, interlace: 1),
            PngTestFiles.ImageData(PngTestFiles.Adam7Scanlines(pixels, width, height, 3)),
            PngTestFiles.Chunk("IEND", []));

        var image = ImageFile.DecodePixels(png, "interlaced.png");

        Assert.Equal((width, height, 3), (image.Width, image.Height, image.Channels));
        Assert.Equal(pixels, image.Data);
    }

    [Fact]
    public void Absurd_dimensions_are_rejected_before_decoding()
    {
        var png = PngTestFiles.File(
            PngTestFiles.Header(1 << 20, 1 << 20, colorType: 2),
            PngTestFiles.ImageData([0, 0, 0, 0]),
            PngTestFiles.Chunk("IEND", []));
        var e = Assert.Throws<ImageFormatException>(() => ImageFile.DecodePixels(png, "huge.png"));
        Assert.StartsWith("huge.png: ", e.Message);
    }

    private static (int, int, int) ToInts((byte R, byte G, byte B) c) => (c.R, c.G, c.B);
}
