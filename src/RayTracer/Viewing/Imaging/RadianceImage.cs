namespace RayTracer.Viewing.Imaging;

/// <summary>Linear RGB radiance per pixel as 32-bit floats, rows top to bottom, channels interleaved.</summary>
public sealed class RadianceImage
{
    public RadianceImage(int width, int height)
        : this(width, height, new float[checked(width * height * 3)])
    {
    }

    public RadianceImage(int width, int height, float[] data)
    {
        if (width <= 0 || height <= 0)
            throw new ArgumentOutOfRangeException(nameof(width), $"Image size must be positive, got {width}x{height}.");
        if (data.Length != checked(width * height * 3))
            throw new ArgumentException($"Pixel buffer holds {data.Length} floats, expected {width * height * 3}.", nameof(data));
        Width = width;
        Height = height;
        Data = data;
    }

    public int Width { get; }
    public int Height { get; }
    public float[] Data { get; }

    public (float R, float G, float B) this[int x, int y]
    {
        get
        {
            var i = 3 * (y * Width + x);
            return (Data[i], Data[i + 1], Data[i + 2]);
        }
        set
        {
            var i = 3 * (y * Width + x);
            (Data[i], Data[i + 1], Data[i + 2]) = value;
        }
    }

    /// <summary>Linear values of 8-bit pixels as (byte / 255)^<paramref name="gamma"/>; gray is spread to RGB, alpha dropped.</summary>
    public static RadianceImage FromPixels(PixelImage pixels, double gamma = 1.0)
    {
        var linear = new float[256];
        for (var i = 0; i < linear.Length; i++)
            linear[i] = (float)Math.Pow(i / 255.0, gamma);
        var image = new RadianceImage(pixels.Width, pixels.Height);
        for (var y = 0; y < pixels.Height; y++)
        for (var x = 0; x < pixels.Width; x++)
        {
            var (r, g, b) = pixels.GetRgb(x, y);
            image[x, y] = (linear[r], linear[g], linear[b]);
        }
        return image;
    }
}
