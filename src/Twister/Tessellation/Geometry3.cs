namespace Twister.Tessellation;

/// <summary>The few vector operations tessellation needs on twistable points and vectors.</summary>
internal static class Geometry3
{
    public static double Distance(TwistablePoint a, TwistablePoint b)
    {
        double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }

    public static TwistablePoint Lerp(TwistablePoint a, TwistablePoint b, double s) =>
        new(a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z));

    /// <summary>α a + β b + γ c with α = 1 − β − γ.</summary>
    public static TwistablePoint Barycentric(TwistablePoint a, TwistablePoint b, TwistablePoint c, double beta, double gamma)
    {
        var alpha = 1 - beta - gamma;
        return new(alpha * a.x + beta * b.x + gamma * c.x, alpha * a.y + beta * b.y + gamma * c.y, alpha * a.z + beta * b.z + gamma * c.z);
    }

    public static double Length(TwistableVector v) => Math.Sqrt(v.x * v.x + v.y * v.y + v.z * v.z);

    public static bool IsFinite(TwistablePoint p) => double.IsFinite(p.x) && double.IsFinite(p.y) && double.IsFinite(p.z);

    public static bool IsFinite(TwistableVector v) => double.IsFinite(v.x) && double.IsFinite(v.y) && double.IsFinite(v.z);
}
