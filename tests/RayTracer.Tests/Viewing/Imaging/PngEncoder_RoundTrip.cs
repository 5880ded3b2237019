using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

public class PngEncoder_RoundTrip
{
    private static PixelImage RandomImage(int width, int height, int channels, int seed)
    {
        var image = new PixelImage(width, height, channels);
        var random = new Random(seed);
        // Mix smooth gradients with noise so every filter type gets exercised by the heuristic.
        for (var y = 0; y < height; y++)
        for (var x = 0; x < width; x++)
        for (var c = 0; c < channels; c++)
            image[x, y, c] = (byte)((x * 3 + y * 5 + c * 40 + (x % 7 == 0 ? random.Next(256) : 0)) & 0xFF);
        return image;
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(4)]
    public void Decoded_pixels_equal_encoded_pixels(int channels)
    {
        var image = RandomImage(37, 23, channels, channels);
        var decoded = PngDecoder.Decode(PngEncoder.Encode(image));
        Assert.Equal(image.Width, decoded.Width);
        Assert.Equal(image.Height, decoded.Height);
        Assert.Equal(channels, decoded.Channels);
        Assert.Equal(image.Data, decoded.Data);
    }

    [Theory]
    [InlineData(PngFilter.None)]
    [InlineData(PngFilter.Sub)]
    [InlineData(PngFilter.Up)]
    [InlineData(PngFilter.Average)]
    [InlineData(PngFilter.Paeth)]
    public void Every_filter_round_trips(byte filter)
    {
        var image = RandomImage(19, 11, 3, filter + 10);
        Assert.Equal(image.Data, PngDecoder.Decode(PngEncoder.Encode(image, filter)).Data);
    }

    [Fact]
    public void Chunks_have_valid_crcs_and_standard_layout()
    {
        var png = PngEncoder.Encode(RandomImage(8, 5, 4, 1));
        var chunks = PngTestFiles.ReadChunks(png).ToList();
        Assert.Equal("IHDR", chunks[0].Type);
        Assert.Equal("IEND", chunks[^1].Type);
        Assert.Contains(chunks, c => c.Type == "IDAT");
        foreach (var (type, data, crc) in chunks)
        {
            var typeAndData = System.Text.Encoding.ASCII.GetBytes(type).Concat(data).ToArray();
            Assert.Equal(PngTestFiles.BitwiseCrc(typeAndData), crc);
        }
        // IHDR: 8-bit RGBA, deflate, adaptive filtering, no interlace.
        Assert.Equal(new byte[] { 0, 0, 0, 8, 0, 0, 0, 5, 8, 6, 0, 0, 0 }, chunks[0].Data);
    }

    [Fact]
    public void Save_writes_atomically_and_leaves_no_temporary_file()
    {
        var dir = Path.Combine(Path.GetTempPath(), "png-save-" + Guid.NewGuid().ToString("N"));
        try
        {
            var path = Path.Combine(dir, "sub", "image.png");
            var image = RandomImage(4, 4, 3, 3);
            PngEncoder.Save(image, path);
            Assert.Equal(image.Data, PngDecoder.Load(path).Data);
            Assert.Equal([path], Directory.GetFiles(Path.GetDirectoryName(path)!));
        }
        finally
        {
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        }
    }
}
