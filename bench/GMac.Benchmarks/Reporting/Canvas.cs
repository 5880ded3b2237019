namespace GMac.Benchmarks.Reporting;

/// <summary>An RGB raster with filled rectangles and a 3×5 digit font: enough for a labelled bar chart.</summary>
public sealed class Canvas
{
    // Rows of 3 bits, top to bottom, for the digits 0-9.
    private static readonly int[][] Digits =
    [
        [7, 5, 5, 5, 7], [2, 6, 2, 2, 7], [7, 1, 7, 4, 7], [7, 1, 7, 1, 7], [5, 5, 7, 1, 1],
        [7, 4, 7, 1, 7], [7, 4, 7, 5, 7], [7, 1, 1, 1, 1], [7, 5, 7, 5, 7], [7, 5, 7, 1, 7],
    ];

    private readonly byte[] _rgb;

    public Canvas(int width, int height, (byte R, byte G, byte B) background)
    {
        Width = width;
        Height = height;
        _rgb = new byte[width * height * 3];
        Fill(0, 0, width, height, background);
    }

    public int Width { get; }
    public int Height { get; }

    public void Fill(int x, int y, int width, int height, (byte R, byte G, byte B) colour)
    {
        var x0 = Math.Max(0, x);
        var y0 = Math.Max(0, y);
        var x1 = Math.Min(Width, x + width);
        var y1 = Math.Min(Height, y + height);
        for (var py = y0; py < y1; py++)
        for (var px = x0; px < x1; px++)
        {
            var i = (py * Width + px) * 3;
            (_rgb[i], _rgb[i + 1], _rgb[i + 2]) = colour;
        }
    }

    /// <summary>Writes a non-negative integer with its top-left corner at (x, y), each font pixel a scale × scale square.</summary>
    public void Number(int x, int y, long value, int scale, (byte R, byte G, byte B) colour)
    {
        foreach (var ch in value.ToString(System.Globalization.CultureInfo.InvariantCulture))
        {
            var rows = Digits[ch - '0'];
            for (var r = 0; r < 5; r++)
            for (var c = 0; c < 3; c++)
                if ((rows[r] & (4 >> c)) != 0)
                    Fill(x + c * scale, y + r * scale, scale, scale, colour);
            x += 4 * scale;
        }
    }

    public static int NumberWidth(long value, int scale) => value.ToString(System.Globalization.CultureInfo.InvariantCulture).Length * 4 * scale - scale;

    public byte[] ToPng() => PngEncoder.Encode(Width, Height, _rgb);
}
