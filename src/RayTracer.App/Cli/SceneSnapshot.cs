using System.Buffers.Binary;
using System.Security.Cryptography;
using RayTracer.Colors;
using RayTracer.Viewing;

namespace RayTracer.Cli;

/// <summary>
/// The exact radiance of a rendered image (width, height, then r, g, b of every pixel as little-endian doubles),
/// so that two renders can be compared bit for bit, and statistics of the difference between two renders.
/// </summary>
internal static class SceneSnapshot
{
    public static byte[] Encode(FrameBuffer image)
    {
        var bytes = new byte[8 + 24 * image.Pixels.Length];
        BinaryPrimitives.WriteInt32LittleEndian(bytes, image.Width);
        BinaryPrimitives.WriteInt32LittleEndian(bytes.AsSpan(4), image.Height);
        var offset = 8;
        foreach (var p in image.Pixels)
        {
            BinaryPrimitives.WriteDoubleLittleEndian(bytes.AsSpan(offset), p.r);
            BinaryPrimitives.WriteDoubleLittleEndian(bytes.AsSpan(offset + 8), p.g);
            BinaryPrimitives.WriteDoubleLittleEndian(bytes.AsSpan(offset + 16), p.b);
            offset += 24;
        }
        return bytes;
    }

    public static (int Width, int Height, RGBColor[] Pixels) Decode(byte[] bytes, string path)
    {
        if (bytes.Length < 8)
            throw new InvalidDataException($"{path}: too short for a snapshot");
        var width = BinaryPrimitives.ReadInt32LittleEndian(bytes);
        var height = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(4));
        if (width <= 0 || height <= 0 || bytes.Length != 8 + 24L * width * height)
            throw new InvalidDataException($"{path}: size {width}x{height} does not match its {bytes.Length} bytes");
        var pixels = new RGBColor[width * height];
        for (var i = 0; i < pixels.Length; i++)
        {
            var o = 8 + 24 * i;
            pixels[i] = new RGBColor(BinaryPrimitives.ReadDoubleLittleEndian(bytes.AsSpan(o)),
                BinaryPrimitives.ReadDoubleLittleEndian(bytes.AsSpan(o + 8)),
                BinaryPrimitives.ReadDoubleLittleEndian(bytes.AsSpan(o + 16)));
        }
        return (width, height, pixels);
    }

    public static string Hash(byte[] bytes) => Convert.ToHexStringLower(SHA256.HashData(bytes))[..16];

    /// <summary>
    /// Per channel: the mean absolute difference, and the mean signed difference with its standard error over
    /// the pixels (two renders agree in expectation when the signed mean lies within a few standard errors of 0).
    /// </summary>
    public static ChannelDifference[] Difference(RGBColor[] a, RGBColor[] b)
    {
        if (a.Length != b.Length)
            throw new ArgumentException($"images of {a.Length} and {b.Length} pixels cannot be compared");
        var result = new ChannelDifference[3];
        for (var channel = 0; channel < 3; channel++)
        {
            double sumAbs = 0, sum = 0, sumSquares = 0;
            for (var i = 0; i < a.Length; i++)
            {
                var d = Channel(a[i], channel) - Channel(b[i], channel);
                sumAbs += Math.Abs(d);
                sum += d;
                sumSquares += d * d;
            }
            var n = a.Length;
            var mean = sum / n;
            var variance = n > 1 ? Math.Max(0, (sumSquares - n * mean * mean) / (n - 1)) : 0;
            result[channel] = new ChannelDifference(sumAbs / n, mean, Math.Sqrt(variance / n));
        }
        return result;
    }

    private static double Channel(RGBColor c, int channel) => channel switch { 0 => c.r, 1 => c.g, _ => c.b };
}

/// <summary>Mean |a − b|, mean (a − b) and the standard error of that mean, over the pixels of one channel.</summary>
internal readonly record struct ChannelDifference(double MeanAbsolute, double Mean, double StandardError);
