using RayTracer.Colors;
using RayTracer.Viewing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

public sealed class ImageFile_RoundTrip : IDisposable
{
    private readonly string _dir = Path.Combine(Path.GetTempPath(), "image-file-" + Guid.NewGuid().ToString("N"));

    public void Dispose()
    {
        if (Directory.Exists(_dir))
            Directory.Delete(_dir, true);
    }

    /// <summary>What a render produces: smooth shading, dark corners, and highlights brighter than white.</summary>
    private static FrameBuffer RenderLike(int width = 29, int height = 17)
    {
        var frame = new FrameBuffer(width, height);
        for (var y = 0; y < height; y++)
        for (var x = 0; x < width; x++)
        {
            var u = (x + 0.5) / width;
            var v = (y + 0.5) / height;
            var highlight = Math.Exp(-40 * ((u - 0.7) * (u - 0.7) + (v - 0.3) * (v - 0.3)));
            frame[x, y] = new RGBColor(0.9 * u * u + 6 * highlight, 0.6 * v + 3 * highlight, 0.02 + 0.3 * u * v + 12 * highlight);
        }
        return frame;
    }

    [Fact]
    public void Png_keeps_a_render_within_8_bit_quantisation()
    {
        var frame = RenderLike();
        const double gamma = 2.2;
        var png = ImageFile.EncodePng(frame.ToImage(GamutMapping.Clamp, gamma));

        var read = ImageFile.DecodeRadiance(png, "render.png", gamma);

        Assert.Equal((frame.Width, frame.Height), (read.Width, read.Height));
        for (var y = 0; y < frame.Height; y++)
        for (var x = 0; x < frame.Width; x++)
        {
            var expected = frame[x, y];
            var (r, g, b) = read[x, y];
            // Rounding happens on the gamma-encoded value, so compare there: at most half a step of 1/255.
            AssertEncodedClose(expected.r, r, gamma);
            AssertEncodedClose(expected.g, g, gamma);
            AssertEncodedClose(expected.b, b, gamma);
        }
    }

    [Fact]
    public void Hdr_keeps_linear_radiance_within_rgbe_precision()
    {
        var frame = RenderLike();
        var hdr = ImageFile.EncodeHdr(frame.ToRadianceImage());
        Assert.True(ImageFile.IsRadiance(hdr));

        var read = ImageFile.DecodeRadiance(hdr, "render.hdr", gamma: 2.2);

        for (var y = 0; y < frame.Height; y++)
        for (var x = 0; x < frame.Width; x++)
        {
            var expected = frame[x, y];
            var (r, g, b) = read[x, y];
            // RGBE shares one exponent per pixel: each channel is exact to about 1% of the brightest one.
            var tolerance = 0.01 * expected.MaxComponent;
            Assert.InRange(r, expected.r - tolerance, expected.r + tolerance);
            Assert.InRange(g, expected.g - tolerance, expected.g + tolerance);
            Assert.InRange(b, expected.b - tolerance, expected.b + tolerance);
        }
        Assert.True(read.Data.Max() > 10, "highlights above white survive in HDR");
    }

    [Theory]
    [InlineData(3)]
    [InlineData(4)]
    public void Png_pixels_read_back_byte_for_byte(int channels)
    {
        var image = new PixelImage(13, 7, channels);
        new Random(channels).NextBytes(image.Data);
        var read = ImageFile.DecodePixels(ImageFile.EncodePng(image), "random.png");
        Assert.Equal(channels, read.Channels);
        Assert.Equal(image.Data, read.Data);
    }

    [Theory]
    [InlineData(".png")]
    [InlineData(".HDR")]
    public void View_plane_writes_the_format_named_by_the_extension_atomically(string extension)
    {
        var frame = RenderLike(8, 5);
        var path = Path.Combine(_dir, "sub", "image" + extension);
        new ViewPlane { Gamma = 2.2 }.SaveImage(frame, path);

        var bytes = File.ReadAllBytes(path);
        Assert.Equal(extension == ".HDR", ImageFile.IsRadiance(bytes));
        Assert.Equal(8, ImageFile.ReadRadiance(path).Width);
        Assert.Equal([path], Directory.GetFiles(Path.GetDirectoryName(path)!));
    }

    [Fact]
    public void View_plane_refuses_other_extensions_and_writes_nothing()
    {
        var path = Path.Combine(_dir, "image.jpg");
        var e = Assert.Throws<ArgumentException>(() => new ViewPlane().SaveImage(RenderLike(2, 2), path));
        Assert.Contains(".png", e.Message);
        Assert.False(File.Exists(path));
    }

    private static void AssertEncodedClose(double linear, float read, double gamma)
    {
        var expected = Math.Pow(Math.Clamp(linear, 0, 1), 1 / gamma);
        var actual = Math.Pow(read, 1 / gamma);
        Assert.InRange(actual, expected - 0.5 / 255 - 1e-6, expected + 0.5 / 255 + 1e-6);
    }
}
