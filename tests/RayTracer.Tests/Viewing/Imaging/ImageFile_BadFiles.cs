using RayTracer.Textures.Images;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

public sealed class ImageFile_BadFiles : IDisposable
{
    private readonly string _dir = Path.Combine(Path.GetTempPath(), "image-bad-" + Guid.NewGuid().ToString("N"));

    public ImageFile_BadFiles() => Directory.CreateDirectory(_dir);

    public void Dispose() => Directory.Delete(_dir, true);

    private static byte[] SamplePng()
    {
        var image = new PixelImage(9, 7, 3);
        new Random(1).NextBytes(image.Data);
        return ImageFile.EncodePng(image);
    }

    [Fact]
    public void A_truncated_png_is_reported_with_its_path()
    {
        var png = SamplePng();
        var path = Path.Combine(_dir, "cut.png");
        File.WriteAllBytes(path, png[..(png.Length / 2)]);

        var e = Assert.Throws<ImageFormatException>(() => ImageTexture.Load(path));

        Assert.Equal(path, e.Path);
        Assert.StartsWith(path + ": ", e.Message);
    }

    [Fact]
    public void Every_truncation_inside_the_pixel_data_is_an_image_format_error()
    {
        var png = SamplePng();
        // From the signature up to the end of the image data (the last 12 bytes are the empty IEND chunk).
        for (var length = 0; length < png.Length - 12; length++)
            Assert.Throws<ImageFormatException>(() => ImageFile.DecodePixels(png[..length], "cut.png"));
    }

    [Fact]
    public void Text_missing_files_and_folders_are_image_format_errors()
    {
        var text = Path.Combine(_dir, "notes.png");
        File.WriteAllText(text, "hello");
        Assert.Contains("expected PNG, JPEG, TGA, BMP or HDR", Assert.Throws<ImageFormatException>(() => ImageFile.ReadRadiance(text)).Message);
        Assert.Equal(Path.Combine(_dir, "none.png"), Assert.Throws<ImageFormatException>(() => ImageFile.ReadPixels(Path.Combine(_dir, "none.png"))).Path);
        Assert.Throws<ImageFormatException>(() => ImageFile.ReadPixels(_dir));
    }
}
