using RayTracer.Colors;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Textures.Images;

/// <summary>
/// Colour from a raster image at (u, v), v = 0 at the bottom row. Nearest-pixel lookup, with bytes
/// converted to linear values by <see cref="Gamma"/> (1 keeps them as stored).
/// </summary>
public sealed class ImageTexture : UVTexture<RGBColor>
{
    private readonly RGBColor[] _texels;

    public ImageTexture(PixelImage image, double gamma = 1.0)
    {
        Width = image.Width;
        Height = image.Height;
        Gamma = gamma;
        _texels = new RGBColor[Width * Height];
        for (var y = 0; y < Height; y++)
        for (var x = 0; x < Width; x++)
        {
            var (r, g, b) = image.GetRgb(x, y);
            _texels[y * Width + x] = new RGBColor(r / 255.0, g / 255.0, b / 255.0).Pow(gamma);
        }
    }

    /// <summary>Loads a PNG; a bad file raises <see cref="PngFormatException"/> naming it.</summary>
    public static ImageTexture Load(string path, double gamma = 1.0) => new(PngDecoder.Load(path), gamma);

    public int Width { get; }
    public int Height { get; }
    public double Gamma { get; }

    public override RGBColor Evaluate(double u, double v)
    {
        var column = Math.Clamp((int)(u * Width), 0, Width - 1);
        var row = Math.Clamp((int)((1 - v) * Height), 0, Height - 1);
        return _texels[row * Width + column];
    }
}
