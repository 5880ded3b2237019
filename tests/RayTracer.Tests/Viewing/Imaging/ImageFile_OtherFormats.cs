using RayTracer.Textures.Images;
using RayTracer.Viewing.Imaging;
using StbImageWriteSharp;

namespace RayTracer.Tests.Viewing.Imaging;

/// <summary>Files in the other formats, written by the stb writer and read back as textures.</summary>
public sealed class ImageFile_OtherFormats : IDisposable
{
    private const int Width = 16, Height = 8;
    private readonly string _dir = Path.Combine(Path.GetTempPath(), "image-formats-" + Guid.NewGuid().ToString("N"));

    public ImageFile_OtherFormats() => Directory.CreateDirectory(_dir);

    public void Dispose() => Directory.Delete(_dir, true);

    /// <summary>Two flat 8 x 8 blocks, aligned with JPEG's blocks so its loss stays small and local.</summary>
    private static byte[] TwoBlocks()
    {
        var data = new byte[Width * Height * 3];
        for (var y = 0; y < Height; y++)
        for (var x = 0; x < Width; x++)
        {
            byte[] colour = x < 8 ? [200, 40, 90] : [30, 160, 220];
            colour.CopyTo(data, (y * Width + x) * 3);
        }
        return data;
    }

    public static TheoryData<string, double> Formats => new() { { ".bmp", 0 }, { ".tga", 0 }, { ".jpg", 8 } };

    [Theory]
    [MemberData(nameof(Formats))]
    public void Eight_bit_formats_read_as_textures(string extension, double toleranceInSteps)
    {
        var data = TwoBlocks();
        var path = Path.Combine(_dir, "blocks" + extension);
        using (var stream = File.Create(path))
        {
            var writer = new ImageWriter();
            switch (extension)
            {
                case ".bmp": writer.WriteBmp(data, Width, Height, ColorComponents.RedGreenBlue, stream); break;
                case ".tga": writer.WriteTga(data, Width, Height, ColorComponents.RedGreenBlue, stream); break;
                default: writer.WriteJpg(data, Width, Height, ColorComponents.RedGreenBlue, stream, 95); break;
            }
        }

        var texture = ImageTexture.Load(path, gamma: 1.0);

        Assert.Equal((Width, Height), (texture.Width, texture.Height));
        var tolerance = (toleranceInSteps + 0.01) / 255;
        foreach (var (x, expected) in new[] { (3, (200, 40, 90)), (12, (30, 160, 220)) })
        {
            // Pixel (x, 4): v runs from the bottom row up.
            var colour = texture.Evaluate((x + 0.5) / Width, 1 - 4.5 / Height);
            Assert.InRange(colour.r, expected.Item1 / 255.0 - tolerance, expected.Item1 / 255.0 + tolerance);
            Assert.InRange(colour.g, expected.Item2 / 255.0 - tolerance, expected.Item2 / 255.0 + tolerance);
            Assert.InRange(colour.b, expected.Item3 / 255.0 - tolerance, expected.Item3 / 255.0 + tolerance);
        }
    }

    [Fact]
    public void Hdr_reads_as_a_linear_texture_without_gamma()
    {
        var image = new RadianceImage(2, 1);
        image[0, 0] = (0.25f, 0.5f, 1f);
        image[1, 0] = (8f, 4f, 2f);
        var path = Path.Combine(_dir, "sky.hdr");
        ImageFile.SaveHdr(image, path);

        var texture = ImageTexture.Load(path, gamma: 2.2);

        var left = texture.Evaluate(0.25, 0.5);
        var right = texture.Evaluate(0.75, 0.5);
        Assert.Equal(0.25, left.r, 0.01);
        Assert.Equal(1.0, left.b, 0.01);
        Assert.Equal(8.0, right.r, 0.08);
        Assert.Equal(2.0, right.b, 0.08);
    }
}
