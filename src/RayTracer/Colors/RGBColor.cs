using RayTracer.Maths;

namespace RayTracer.Colors;

/// <summary>Linear RGB radiance or reflectance; colours multiply channel by channel.</summary>
public struct RGBColor : ITuple3<RGBColor>
{
    public double r;
    public double g;
    public double b;

    public static readonly RGBColor Black = new(0, 0, 0);
    public static readonly RGBColor White = new(1, 1, 1);

    public RGBColor(double r, double g, double b)
    {
        this.r = r;
        this.g = g;
        this.b = b;
    }

    public RGBColor(double c) : this(c, c, c)
    {
    }

    public static RGBColor operator +(RGBColor a, RGBColor c) => new(a.r + c.r, a.g + c.g, a.b + c.b);
    public static RGBColor operator -(RGBColor a, RGBColor c) => new(a.r - c.r, a.g - c.g, a.b - c.b);
    public static RGBColor operator *(RGBColor a, RGBColor c) => new(a.r * c.r, a.g * c.g, a.b * c.b);
    public static RGBColor operator *(RGBColor a, double s) => new(a.r * s, a.g * s, a.b * s);
    public static RGBColor operator *(double s, RGBColor a) => new(a.r * s, a.g * s, a.b * s);
    public static RGBColor operator /(RGBColor a, double s)
    {
        double inv = 1.0 / s;
        return new(a.r * inv, a.g * inv, a.b * inv);
    }

    /// <summary>Raises each component to <paramref name="p"/> (gamma correction).</summary>
    public readonly RGBColor Pow(double p) => new(Math.Pow(r, p), Math.Pow(g, p), Math.Pow(b, p));

    public readonly double Average => (r + g + b) / 3.0;
    public readonly double MaxComponent => Math.Max(r, Math.Max(g, b));

    static RGBColor ITuple3<RGBColor>.Create(double first, double second, double third) => new(first, second, third);

    public readonly (double First, double Second, double Third) Components => (r, g, b);

    public readonly bool Equals(RGBColor other) => Tuple3.Equal(this, other);
    public override readonly bool Equals(object? obj) => obj is RGBColor c && Equals(c);
    public override readonly int GetHashCode() => Tuple3.Hash(this);
    public static bool operator ==(RGBColor a, RGBColor c) => a.Equals(c);
    public static bool operator !=(RGBColor a, RGBColor c) => !a.Equals(c);
    public override readonly string ToString() => Tuple3.Format(this, "rgb(", ")");
}
