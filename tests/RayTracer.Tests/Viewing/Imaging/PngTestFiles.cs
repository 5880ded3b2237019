using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace RayTracer.Tests.Viewing.Imaging;

/// <summary>Builds PNG byte streams by hand from the specification, independently of the libraries under test.</summary>
internal static class PngTestFiles
{
    /// <summary>Bit-by-bit CRC-32, deliberately not table driven, as an independent check.</summary>
    public static uint BitwiseCrc(ReadOnlySpan<byte> data)
    {
        var crc = 0xFFFFFFFFu;
        foreach (var b in data)
        {
            crc ^= b;
            for (var k = 0; k < 8; k++)
                crc = (crc >> 1) ^ (0xEDB88320u & (uint)-(int)(crc & 1));
        }
        return ~crc;
    }

    public static byte[] Chunk(string type, byte[] data)
    {
        var typeAndData = Encoding.ASCII.GetBytes(type).Concat(data).ToArray();
        var result = new byte[12 + data.Length];
        BinaryPrimitives.WriteInt32BigEndian(result, data.Length);
        typeAndData.CopyTo(result, 4);
        BinaryPrimitives.WriteUInt32BigEndian(result.AsSpan(8 + data.Length), BitwiseCrc(typeAndData));
        return result;
    }

    public static byte[] Header(int width, int height, byte colorType, byte bitDepth = 8, byte interlace = 0)
    {
        var data = new byte[13];
        BinaryPrimitives.WriteInt32BigEndian(data, width);
        BinaryPrimitives.WriteInt32BigEndian(data.AsSpan(4), height);
        data[8] = bitDepth;
        data[9] = colorType;
        data[12] = interlace;
        return Chunk("IHDR", data);
    }

    /// <summary>Zlib-compresses scanlines that each already start with their filter byte.</summary>
    public static byte[] ImageData(byte[] filteredScanlines)
    {
        using var ms = new MemoryStream();
        using (var z = new ZLibStream(ms, CompressionLevel.Fastest, leaveOpen: true))
            z.Write(filteredScanlines);
        return Chunk("IDAT", ms.ToArray());
    }

    /// <summary>
    /// Scanlines of an Adam7-interlaced image, every row unfiltered: the seven passes in order, each the
    /// pixels at (x0 + i·dx, y0 + j·dy), empty passes left out as the specification says.
    /// </summary>
    public static byte[] Adam7Scanlines(byte[] pixels, int width, int height, int bytesPerPixel)
    {
        (int X0, int Y0, int Dx, int Dy)[] passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)];
        var output = new List<byte>();
        foreach (var (x0, y0, dx, dy) in passes)
        {
            if (x0 >= width || y0 >= height)
                continue;
            for (var y = y0; y < height; y += dy)
            {
                output.Add(0);
                for (var x = x0; x < width; x += dx)
                    output.AddRange(pixels.AsSpan((y * width + x) * bytesPerPixel, bytesPerPixel).ToArray());
            }
        }
        return [.. output];
    }

    public static byte[] File(params byte[][] chunks) =>
        new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }.Concat(chunks.SelectMany(c => c)).ToArray();
}
