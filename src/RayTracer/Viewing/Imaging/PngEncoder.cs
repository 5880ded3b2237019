using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;
using SafeFiles;

namespace RayTracer.Viewing.Imaging;

/// <summary>
/// Writes 8-bit gray, gray+alpha, RGB and RGBA PNG files. Each scanline gets the filter that
/// minimises the sum of absolute filtered bytes (the usual heuristic), unless a fixed filter is requested.
/// </summary>
public static class PngEncoder
{
    internal static readonly byte[] Signature = [137, 80, 78, 71, 13, 10, 26, 10];

    /// <summary>Encodes an image; <paramref name="fixedFilter"/> forces one filter type for every row.</summary>
    public static byte[] Encode(PixelImage image, byte? fixedFilter = null)
    {
        using var output = new MemoryStream();
        output.Write(Signature);

        Span<byte> header = stackalloc byte[13];
        BinaryPrimitives.WriteInt32BigEndian(header, image.Width);
        BinaryPrimitives.WriteInt32BigEndian(header[4..], image.Height);
        header[8] = 8;
        header[9] = ColorType(image.Channels);
        header[10] = 0; // deflate
        header[11] = 0; // adaptive filtering
        header[12] = 0; // no interlace
        WriteChunk(output, "IHDR", header);
        WriteChunk(output, "IDAT", CompressScanlines(image, fixedFilter));
        WriteChunk(output, "IEND", ReadOnlySpan<byte>.Empty);
        return output.ToArray();
    }

    /// <summary>
    /// Writes the PNG atomically (see <see cref="AtomicFile"/>), so a reader never sees a partly
    /// written image; the folder is created if needed.
    /// </summary>
    public static void Save(PixelImage image, string path)
    {
        var bytes = Encode(image);
        var directory = Path.GetDirectoryName(Path.GetFullPath(path));
        if (!string.IsNullOrEmpty(directory))
            Directory.CreateDirectory(directory);
        AtomicFile.Write(path, bytes);
    }

    private static byte ColorType(int channels) => channels switch
    {
        1 => 0,
        2 => 4,
        3 => 2,
        4 => 6,
        _ => throw new ArgumentOutOfRangeException(nameof(channels)),
    };

    private static byte[] CompressScanlines(PixelImage image, byte? fixedFilter)
    {
        var stride = image.Stride;
        var bpp = image.Channels;
        var previous = new byte[stride];
        var candidate = new byte[stride];
        var best = new byte[stride];

        using var compressed = new MemoryStream();
        using (var zlib = new ZLibStream(compressed, CompressionLevel.Optimal, leaveOpen: true))
        {
            for (var y = 0; y < image.Height; y++)
            {
                var row = image.Data.AsSpan(y * stride, stride);
                byte chosen;
                if (fixedFilter is { } f)
                {
                    chosen = f;
                    PngFilter.Apply(f, row, previous, bpp, best);
                }
                else
                {
                    chosen = PngFilter.None;
                    var bestScore = long.MaxValue;
                    for (byte type = PngFilter.None; type <= PngFilter.Paeth; type++)
                    {
                        PngFilter.Apply(type, row, previous, bpp, candidate);
                        long score = 0;
                        foreach (var v in candidate)
                            score += Math.Abs((int)(sbyte)v);
                        if (score < bestScore)
                        {
                            bestScore = score;
                            chosen = type;
                            candidate.CopyTo(best, 0);
                        }
                    }
                }
                zlib.WriteByte(chosen);
                zlib.Write(best);
                row.CopyTo(previous);
            }
        }
        return compressed.ToArray();
    }

    private static void WriteChunk(Stream output, string type, ReadOnlySpan<byte> data)
    {
        Span<byte> buffer = stackalloc byte[4];
        BinaryPrimitives.WriteInt32BigEndian(buffer, data.Length);
        output.Write(buffer);
        var typeBytes = Encoding.ASCII.GetBytes(type);
        output.Write(typeBytes);
        output.Write(data);
        var crc = Crc32.Update(Crc32.Compute(typeBytes), data);
        BinaryPrimitives.WriteUInt32BigEndian(buffer, crc);
        output.Write(buffer);
    }
}
