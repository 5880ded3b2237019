namespace RayTracer.Maths;

/// <summary>A point in 2D (sample positions, pixel coordinates).</summary>
public struct Point2D : IEquatable<Point2D>
{
    public double x;
    public double y;

    public Point2D(double x, double y)
    {
        this.x = x;
        this.y = y;
    }

    public static Point2D operator +(Point2D a, Point2D b) => new(a.x + b.x, a.y + b.y);
    public static Point2D operator -(Point2D a, Point2D b) => new(a.x - b.x, a.y - b.y);
    public static Point2D operator *(Point2D a, double s) => new(a.x * s, a.y * s);
    public static Point2D operator *(double s, Point2D a) => new(a.x * s, a.y * s);

    public readonly bool Equals(Point2D other) => x == other.x && y == other.y;
    public override readonly bool Equals(object? obj) => obj is Point2D p && Equals(p);
    public override readonly int GetHashCode() => HashCode.Combine(x, y);
    public static bool operator ==(Point2D a, Point2D b) => a.Equals(b);
    public static bool operator !=(Point2D a, Point2D b) => !a.Equals(b);
    public override readonly string ToString() => FormattableString.Invariant($"({x}, {y})");
}
