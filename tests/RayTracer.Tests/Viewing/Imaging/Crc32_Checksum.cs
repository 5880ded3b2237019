using System.Text;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Viewing.Imaging;

public class Crc32_Checksum
{
    [Fact]
    public void Matches_the_standard_check_value()
    {
        // The CRC-32 catalogue check value for the ASCII string "123456789".
        Assert.Equal(0xCBF43926u, Crc32.Compute(Encoding.ASCII.GetBytes("123456789")));
    }

    [Fact]
    public void Agrees_with_a_bitwise_implementation_and_is_incremental()
    {
        var random = new Random(7);
        var data = new byte[1000];
        random.NextBytes(data);
        Assert.Equal(PngTestFiles.BitwiseCrc(data), Crc32.Compute(data));
        Assert.Equal(Crc32.Compute(data), Crc32.Update(Crc32.Compute(data.AsSpan(0, 333)), data.AsSpan(333)));
    }
}
