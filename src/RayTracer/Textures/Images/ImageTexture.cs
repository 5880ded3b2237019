using RayTracer.Colors;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Textures.Images;

/// <summary>
/// Colour from a raster image at (u, v), v = 0 at the bottom row, by nearest-pixel lookup of linear
/// radiance (8-bit images are made linear by a gamma on loading; HDR images are linear already).
/// </summary>
public sealed class ImageTexture : UVTexture<RGBColor>
{
    private readonly RGBColor[] _texels;

    /// <summary>An 8-bit image, its bytes made linear as (byte / 255)^<paramref name="gamma"/>.</summary>
    public ImageTexture(PixelImage image, double gamma = 1.0)
        : this(RadianceImage.FromPixels(image, gamma))
    {
    }

    /// <summary>A texture of linear radiance, used as stored.</summary>
    public ImageTexture(RadianceImage image)
    {
        Width = image.Width;
        Height = image.Height;
        _texels = new RGBColor[Width * Height];
        for (var y = 0; y < Height; y++)
        for (var x = 0; x < Width; x++)
        {
            var (r, g, b) = image[x, y];
            _texels[y * Width + x] = new RGBColor(r, g, b);
        }
    }

    /// <summary>
    /// Loads a PNG, JPEG, TGA, BMP or HDR file; <paramref name="gamma"/> applies to 8-bit formats only.
    /// A bad file raises <see cref="ImageFormatException"/> naming it.
    /// </summary>
    public static ImageTexture Load(string path, double gamma = 1.0) => new(ImageFile.ReadRadiance(path, gamma));

    public int Width { get; }
    public int Height { get; }

    public override RGBColor Evaluate(double u, double v)
    {
        var column = Math.Clamp((int)(u * Width), 0, Width - 1);
        var row = Math.Clamp((int)((1 - v) * Height), 0, Height - 1);
        return _texels[row * Width + column];
    }
}
