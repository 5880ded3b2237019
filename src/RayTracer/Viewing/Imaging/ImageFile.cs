using SafeFiles;
using StbImageSharp;
using StbImageWriteSharp;
using ReadComponents = StbImageSharp.ColorComponents;
using WriteComponents = StbImageWriteSharp.ColorComponents;

namespace RayTracer.Viewing.Imaging;

/// <summary>
/// Reads PNG (any bit depth, interlaced or not), JPEG, TGA, BMP and Radiance HDR images, and writes PNG
/// and HDR, through the stb image libraries. Files are written atomically, a FIFO is
/// written into, and other special files are refused rather than replaced (see <see cref="OutputFile"/>).
/// </summary>
public static class ImageFile
{
    /// <summary>The extensions a render can be written as, lower case with the dot.</summary>
    public static IReadOnlyList<string> OutputExtensions { get; } = [".png", ".hdr"];

    public const string ReadableFormats = "PNG, JPEG, TGA, BMP or HDR";

    /// <summary>Larger images are refused before decoding rather than exhausting memory.</summary>
    public const long MaxPixels = 1L << 26;

    public static bool IsOutputPath(string path) =>
        OutputExtensions.Contains(Path.GetExtension(path).ToLowerInvariant());

    /// <summary>Whether <paramref name="bytes"/> start like a Radiance HDR file (linear floats, no gamma).</summary>
    public static bool IsRadiance(ReadOnlySpan<byte> bytes) =>
        bytes.StartsWith("#?RADIANCE\n"u8) || bytes.StartsWith("#?RGBE\n"u8);

    public static void WritePng(PixelImage image, Stream stream) =>
        new ImageWriter().WritePng(image.Data, image.Width, image.Height, (WriteComponents)image.Channels, stream);

    public static unsafe void WriteHdr(RadianceImage image, Stream stream)
    {
        // stb writes through a callback; the delegate copies each run of bytes straight into the stream.
        var sink = new StbImageWrite.delegate0((_, data, size) => stream.Write(new ReadOnlySpan<byte>(data, size)));
        fixed (float* pixels = image.Data)
        {
            if (StbImageWrite.stbi_write_hdr_to_func(sink, null, image.Width, image.Height, 3, pixels) == 0)
                throw new IOException("the HDR writer refused the image");
        }
    }

    public static byte[] EncodePng(PixelImage image) => Encode(stream => WritePng(image, stream));

    public static byte[] EncodeHdr(RadianceImage image) => Encode(stream => WriteHdr(image, stream));

    /// <summary>Writes a PNG atomically, creating the folder if needed.</summary>
    public static void SavePng(PixelImage image, string path) => Save(path, stream => WritePng(image, stream));

    /// <summary>Writes a Radiance HDR file atomically, creating the folder if needed.</summary>
    public static void SaveHdr(RadianceImage image, string path) => Save(path, stream => WriteHdr(image, stream));

    /// <summary>8-bit pixels of any readable image (HDR is tone mapped by the decoder); as RGB, or RGBA if it has alpha.</summary>
    public static PixelImage ReadPixels(string path) => DecodePixels(ReadAllBytes(path), path);

    /// <summary>Linear RGB of any readable image: HDR as stored, 8-bit channels as (byte / 255)^<paramref name="gamma"/>.</summary>
    public static RadianceImage ReadRadiance(string path, double gamma = 1.0) => DecodeRadiance(ReadAllBytes(path), path, gamma);

    public static PixelImage DecodePixels(byte[] bytes, string name)
    {
        var info = Inspect(bytes, name);
        var alpha = info.ColorComponents is ReadComponents.GreyAlpha or ReadComponents.RedGreenBlueAlpha;
        var wanted = alpha ? ReadComponents.RedGreenBlueAlpha : ReadComponents.RedGreenBlue;
        var result = Decode(name, () => ImageResult.FromMemory(bytes, wanted));
        return new PixelImage(result.Width, result.Height, (int)wanted, result.Data);
    }

    public static RadianceImage DecodeRadiance(byte[] bytes, string name, double gamma = 1.0)
    {
        Inspect(bytes, name);
        if (IsRadiance(bytes))
        {
            var hdr = Decode(name, () => ImageResultFloat.FromMemory(bytes, ReadComponents.RedGreenBlue));
            return new RadianceImage(hdr.Width, hdr.Height, hdr.Data);
        }

        var ldr = Decode(name, () => ImageResult.FromMemory(bytes, ReadComponents.RedGreenBlue));
        return RadianceImage.FromPixels(new PixelImage(ldr.Width, ldr.Height, 3, ldr.Data), gamma);
    }

    private static ImageInfo Inspect(byte[] bytes, string name)
    {
        ImageInfo? info;
        try
        {
            using var stream = new MemoryStream(bytes, writable: false);
            info = ImageInfo.FromStream(stream);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            info = null;
        }

        if (info is not { } known)
            throw new ImageFormatException(name, $"not an image this program can read (expected {ReadableFormats})");
        if (known.Width <= 0 || known.Height <= 0 || (long)known.Width * known.Height > MaxPixels)
            throw new ImageFormatException(name, $"image size {known.Width}x{known.Height} is outside 1 to {MaxPixels:N0} pixels");
        return known;
    }

    private static T Decode<T>(string name, Func<T> decode)
    {
        try
        {
            return decode();
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The decoder reports damage as terse reasons ("outofdata", "bad huffman code"); keep them for the user.
            throw new ImageFormatException(name, $"damaged or unsupported image ({e.Message})", e);
        }
    }

    private static byte[] ReadAllBytes(string path)
    {
        try
        {
            return File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new ImageFormatException(path, $"cannot read the file: {e.Message}", e);
        }
    }

    private static byte[] Encode(Action<Stream> write)
    {
        using var stream = new MemoryStream();
        write(stream);
        return stream.ToArray();
    }

    /// <summary>Creates the folder if needed; see <see cref="OutputFile"/> for what is done to a file already there.</summary>
    private static void Save(string path, Action<Stream> write)
    {
        var directory = Path.GetDirectoryName(Path.GetFullPath(path));
        if (!string.IsNullOrEmpty(directory))
            Directory.CreateDirectory(directory);
        OutputFile.Write(path, write);
    }
}
