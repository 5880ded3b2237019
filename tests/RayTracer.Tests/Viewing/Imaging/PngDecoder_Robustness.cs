using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

public class PngDecoder_Robustness
{
    private static byte[] SamplePng()
    {
        var image = new PixelImage(9, 7, 4);
        new Random(1).NextBytes(image.Data);
        return PngEncoder.Encode(image);
    }

    [Fact]
    public void Every_truncation_is_rejected_with_a_format_error()
    {
        var png = SamplePng();
        for (var length = 0; length < png.Length; length++)
            Assert.Throws<PngFormatException>(() => PngDecoder.Decode(png.AsSpan(0, length)));
    }

    [Fact]
    public void Every_single_byte_corruption_is_detected_or_harmless()
    {
        var png = SamplePng();
        var original = PngDecoder.Decode(png).Data;
        for (var i = 0; i < png.Length; i++)
        {
            var corrupt = (byte[])png.Clone();
            corrupt[i] ^= 0x5A;
            try
            {
                // A flip the CRCs cannot see (none should exist) would have to leave the pixels intact.
                Assert.Equal(original, PngDecoder.Decode(corrupt).Data);
            }
            catch (PngFormatException)
            {
            }
        }
    }

    [Fact]
    public void Absurd_dimensions_are_rejected_before_allocating()
    {
        var png = PngTestFiles.File(
            PngTestFiles.Header(1 << 20, 1 << 20, colorType: 2),
            PngTestFiles.ImageData([0, 0, 0, 0]),
            PngTestFiles.Chunk("IEND", []));
        Assert.Contains("exceeds", Assert.Throws<PngFormatException>(() => PngDecoder.Decode(png)).Message);
    }
}
