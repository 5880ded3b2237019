namespace RayTracer.Viewing.Imaging;

/// <summary>The five PNG scanline filters (ISO/IEC 15948, §9) with their inverse.</summary>
public static class PngFilter
{
    public const byte None = 0, Sub = 1, Up = 2, Average = 3, Paeth = 4;

    public static byte PaethPredictor(int a, int b, int c)
    {
        var p = a + b - c;
        var pa = Math.Abs(p - a);
        var pb = Math.Abs(p - b);
        var pc = Math.Abs(p - c);
        if (pa <= pb && pa <= pc) return (byte)a;
        return pb <= pc ? (byte)b : (byte)c;
    }

    /// <summary>Filters <paramref name="row"/> into <paramref name="output"/>; <paramref name="previous"/> is all zero for the first row.</summary>
    public static void Apply(byte type, ReadOnlySpan<byte> row, ReadOnlySpan<byte> previous, int bytesPerPixel, Span<byte> output)
    {
        for (var i = 0; i < row.Length; i++)
        {
            int a = i >= bytesPerPixel ? row[i - bytesPerPixel] : 0;
            int b = previous[i];
            int c = i >= bytesPerPixel ? previous[i - bytesPerPixel] : 0;
            var predicted = type switch
            {
                None => 0,
                Sub => a,
                Up => b,
                Average => (a + b) >> 1,
                Paeth => PaethPredictor(a, b, c),
                _ => throw new ArgumentOutOfRangeException(nameof(type), $"Unknown PNG filter type {type}."),
            };
            output[i] = (byte)(row[i] - predicted);
        }
    }

    /// <summary>Undoes a filter in place; <paramref name="previous"/> holds the already reconstructed row above.</summary>
    public static void Reverse(byte type, Span<byte> row, ReadOnlySpan<byte> previous, int bytesPerPixel)
    {
        for (var i = 0; i < row.Length; i++)
        {
            int a = i >= bytesPerPixel ? row[i - bytesPerPixel] : 0;
            int b = previous[i];
            int c = i >= bytesPerPixel ? previous[i - bytesPerPixel] : 0;
            var predicted = type switch
            {
                None => 0,
                Sub => a,
                Up => b,
                Average => (a + b) >> 1,
                Paeth => PaethPredictor(a, b, c),
                _ => throw new PngFormatException($"Unknown PNG filter type {type}."),
            };
            row[i] = (byte)(row[i] + predicted);
        }
    }
}
