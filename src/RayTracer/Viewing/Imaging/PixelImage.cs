namespace RayTracer.Viewing.Imaging;

/// <summary>
/// An 8-bit-per-channel raster, rows top to bottom, channels interleaved
/// (1 = gray, 2 = gray+alpha, 3 = RGB, 4 = RGBA).
/// </summary>
public sealed class PixelImage
{
    public int Width { get; }
    public int Height { get; }
    public int Channels { get; }
    public byte[] Data { get; }

    public PixelImage(int width, int height, int channels)
        : this(width, height, channels, new byte[checked(width * height * channels)])
    {
    }

    public PixelImage(int width, int height, int channels, byte[] data)
    {
        if (width <= 0 || height <= 0)
            throw new ArgumentOutOfRangeException(nameof(width), $"Image size must be positive, got {width}x{height}.");
        if (channels is < 1 or > 4)
            throw new ArgumentOutOfRangeException(nameof(channels), $"Channels must be 1 to 4, got {channels}.");
        if (data.Length != checked(width * height * channels))
            throw new ArgumentException($"Pixel buffer holds {data.Length} bytes, expected {width * height * channels}.", nameof(data));
        Width = width;
        Height = height;
        Channels = channels;
        Data = data;
    }

    public byte this[int x, int y, int channel]
    {
        get => Data[(y * Width + x) * Channels + channel];
        set => Data[(y * Width + x) * Channels + channel] = value;
    }

    /// <summary>Colour of a pixel as RGB bytes, expanding gray to all three channels.</summary>
    public (byte R, byte G, byte B) GetRgb(int x, int y)
    {
        var i = (y * Width + x) * Channels;
        return Channels >= 3 ? (Data[i], Data[i + 1], Data[i + 2]) : (Data[i], Data[i], Data[i]);
    }
}
