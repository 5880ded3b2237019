using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace RayTracer.Viewing.Imaging;

/// <summary>
/// Reads non-interlaced 8-bit PNGs (gray, gray+alpha, RGB, RGBA, palette) and checks every chunk CRC.
/// Palette images are expanded to RGB, or RGBA when a tRNS chunk is present.
/// </summary>
public static class PngDecoder
{
    /// <summary>Largest accepted image (pixels), so a hostile header cannot ask for an absurd buffer.</summary>
    public const long MaxPixels = 1L << 28;

    public static PixelImage Load(string path)
    {
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new PngFormatException($"{path}: cannot read file: {e.Message}", e);
        }
        try
        {
            return Decode(bytes);
        }
        catch (PngFormatException e)
        {
            throw new PngFormatException($"{path}: {e.Message}", e);
        }
    }

    public static PixelImage Decode(ReadOnlySpan<byte> png)
    {
        if (png.Length < 8 || !png[..8].SequenceEqual(PngEncoder.Signature))
            throw new PngFormatException("not a PNG file (bad signature).");

        int width = 0, height = 0;
        byte colorType = 0;
        var sawHeader = false;
        var sawEnd = false;
        byte[]? palette = null;
        byte[]? transparency = null;
        using var idat = new MemoryStream();

        var offset = 8;
        while (offset < png.Length && !sawEnd)
        {
            if (png.Length - offset < 12)
                throw new PngFormatException($"truncated chunk at byte {offset}.");
            var length = BinaryPrimitives.ReadInt32BigEndian(png[offset..]);
            if (length < 0 || length > png.Length - offset - 12)
                throw new PngFormatException($"chunk length {length} at byte {offset} runs past the end of the file.");
            var typeAndData = png.Slice(offset + 4, 4 + length);
            var type = Encoding.ASCII.GetString(typeAndData[..4]);
            var data = typeAndData[4..];
            var storedCrc = BinaryPrimitives.ReadUInt32BigEndian(png[(offset + 8 + length)..]);
            if (Crc32.Compute(typeAndData) != storedCrc)
                throw new PngFormatException($"CRC mismatch in chunk '{type}' at byte {offset}.");
            offset += 12 + length;

            if (!sawHeader && type != "IHDR")
                throw new PngFormatException("first chunk is not IHDR.");
            switch (type)
            {
                case "IHDR":
                    if (length != 13)
                        throw new PngFormatException("IHDR chunk must be 13 bytes.");
                    width = BinaryPrimitives.ReadInt32BigEndian(data);
                    height = BinaryPrimitives.ReadInt32BigEndian(data[4..]);
                    var bitDepth = data[8];
                    colorType = data[9];
                    if (width <= 0 || height <= 0)
                        throw new PngFormatException($"invalid image size {width}x{height}.");
                    if ((long)width * height > MaxPixels)
                        throw new PngFormatException($"image size {width}x{height} exceeds the supported {MaxPixels} pixels.");
                    if (bitDepth != 8)
                        throw new PngFormatException($"bit depth {bitDepth} is not supported (only 8).");
                    if (colorType is not (0 or 2 or 3 or 4 or 6))
                        throw new PngFormatException($"invalid color type {colorType}.");
                    if (data[10] != 0 || data[11] != 0)
                        throw new PngFormatException("unknown compression or filter method.");
                    if (data[12] != 0)
                        throw new PngFormatException("interlaced PNGs are not supported.");
                    sawHeader = true;
                    break;
                case "PLTE":
                    if (length % 3 != 0 || length == 0 || length > 768)
                        throw new PngFormatException("invalid PLTE chunk length.");
                    palette = data.ToArray();
                    break;
                case "tRNS":
                    transparency = data.ToArray();
                    break;
                case "IDAT":
                    idat.Write(data);
                    break;
                case "IEND":
                    sawEnd = true;
                    break;
                default:
                    // Ancillary chunks (lower-case first letter) may be skipped; critical ones may not.
                    if (char.IsUpper(type[0]))
                        throw new PngFormatException($"unsupported critical chunk '{type}'.");
                    break;
            }
        }
        if (!sawHeader)
            throw new PngFormatException("missing IHDR chunk.");
        if (!sawEnd)
            throw new PngFormatException("missing IEND chunk (file truncated?).");
        if (colorType == 3 && palette is null)
            throw new PngFormatException("palette image without PLTE chunk.");

        var samples = colorType switch { 0 => 1, 2 => 3, 3 => 1, 4 => 2, _ => 4 };
        var raw = Unfilter(Inflate(idat), width, height, samples);
        if (colorType != 3)
            return new PixelImage(width, height, samples, raw);
        return ExpandPalette(raw, width, height, palette!, transparency);
    }

    private static byte[] Inflate(MemoryStream idat)
    {
        idat.Position = 0;
        using var output = new MemoryStream();
        try
        {
            using var zlib = new ZLibStream(idat, CompressionMode.Decompress);
            zlib.CopyTo(output);
        }
        catch (InvalidDataException e)
        {
            throw new PngFormatException($"corrupt image data: {e.Message}", e);
        }
        return output.ToArray();
    }

    private static byte[] Unfilter(byte[] filtered, int width, int height, int bpp)
    {
        var stride = checked(width * bpp);
        if (filtered.Length < (long)(stride + 1) * height)
            throw new PngFormatException($"image data holds {filtered.Length} bytes, expected {(long)(stride + 1) * height}.");
        var pixels = new byte[stride * height];
        var zero = new byte[stride];
        for (var y = 0; y < height; y++)
        {
            var type = filtered[y * (stride + 1)];
            var row = pixels.AsSpan(y * stride, stride);
            filtered.AsSpan(y * (stride + 1) + 1, stride).CopyTo(row);
            ReadOnlySpan<byte> previous = y == 0 ? zero : pixels.AsSpan((y - 1) * stride, stride);
            if (type > PngFilter.Paeth)
                throw new PngFormatException($"unknown filter type {type} on row {y}.");
            PngFilter.Reverse(type, row, previous, bpp);
        }
        return pixels;
    }

    private static PixelImage ExpandPalette(byte[] indices, int width, int height, byte[] palette, byte[]? alpha)
    {
        var channels = alpha is null ? 3 : 4;
        var image = new PixelImage(width, height, channels);
        var entries = palette.Length / 3;
        for (var i = 0; i < indices.Length; i++)
        {
            int index = indices[i];
            if (index >= entries)
                throw new PngFormatException($"palette index {index} out of range (palette has {entries} entries).");
            var o = i * channels;
            image.Data[o] = palette[3 * index];
            image.Data[o + 1] = palette[3 * index + 1];
            image.Data[o + 2] = palette[3 * index + 2];
            if (alpha is not null)
                image.Data[o + 3] = index < alpha.Length ? alpha[index] : (byte)255;
        }
        return image;
    }
}
