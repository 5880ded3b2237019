using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace RayTracer.Tests.Viewing.Imaging;

/// <summary>Builds PNG byte streams by hand from the specification, independently of the encoder.</summary>
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

    public static byte[] File(params byte[][] chunks) =>
        new byte[] { 137, 80, 78, 71, 13, 10, 26, 10 }.Concat(chunks.SelectMany(c => c)).ToArray();

    public static IEnumerable<(string Type, byte[] Data, uint Crc)> ReadChunks(byte[] png)
    {
        var offset = 8;
        while (offset < png.Length)
        {
            var length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(offset));
            var type = Encoding.ASCII.GetString(png, offset + 4, 4);
            var data = png.AsSpan(offset + 8, length).ToArray();
            var crc = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(offset + 8 + length));
            yield return (type, data, crc);
            offset += 12 + length;
        }
    }
}
