using RayTracer.Colors;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Viewing;

/// <summary>Linear radiance per pixel, row 0 at the top; tone mapped to 8 bits for PNG, kept linear for HDR.</summary>
public sealed class FrameBuffer
{
    private readonly RGBColor[] _pixels;

    public int Width { get; }
    public int Height { get; }

    public FrameBuffer(int width, int height)
    {
        if (width <= 0 || height <= 0)
            throw new ArgumentOutOfRangeException(nameof(width), $"Image size must be positive, got {width}x{height}.");
        Width = width;
        Height = height;
        _pixels = new RGBColor[width * height];
    }

    public RGBColor this[int column, int row]
    {
        get => _pixels[row * Width + column];
        set => _pixels[row * Width + column] = value;
    }

    public ReadOnlySpan<RGBColor> Pixels => _pixels;

    public static RGBColor MapToGamut(RGBColor c, GamutMapping mapping)
    {
        var max = c.MaxComponent;
        if (max <= 1.0)
            return c;
        return mapping switch
        {
            GamutMapping.MaxToOne => c / max,
            GamutMapping.Highlight => new RGBColor(1, 0, 0),
            _ => new RGBColor(Math.Min(c.r, 1.0), Math.Min(c.g, 1.0), Math.Min(c.b, 1.0)),
        };
    }

    /// <summary>8-bit value of a linear channel: gamut mapping, gamma, then rounding.</summary>
    public static byte ToByte(double v, double gamma)
    {
        if (!(v > 0)) return 0; // also maps NaN to black rather than to an arbitrary byte
        var encoded = gamma == 1.0 ? v : Math.Pow(v, 1.0 / gamma);
        return (byte)Math.Clamp((int)Math.Round(encoded * 255.0), 0, 255);
    }

    public PixelImage ToImage(GamutMapping mapping, double gamma)
    {
        var image = new PixelImage(Width, Height, 3);
        for (var i = 0; i < _pixels.Length; i++)
        {
            var c = MapToGamut(_pixels[i], mapping);
            image.Data[3 * i] = ToByte(c.r, gamma);
            image.Data[3 * i + 1] = ToByte(c.g, gamma);
            image.Data[3 * i + 2] = ToByte(c.b, gamma);
        }
        return image;
    }

    public PixelImage ToImage(ViewPlane vp) => ToImage(vp.GamutMapping, vp.Gamma);

    /// <summary>The radiance as stored, for formats that keep it linear (no gamut mapping, no gamma).</summary>
    public RadianceImage ToRadianceImage()
    {
        var image = new RadianceImage(Width, Height);
        for (var i = 0; i < _pixels.Length; i++)
        {
            var c = _pixels[i];
            image.Data[3 * i] = (float)c.r;
            image.Data[3 * i + 1] = (float)c.g;
            image.Data[3 * i + 2] = (float)c.b;
        }
        return image;
    }
}
