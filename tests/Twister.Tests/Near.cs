using Twister;

namespace Twister.Tests;

/// <summary>Component-wise comparisons with an absolute tolerance scaled by the size of the expected value.</summary>
internal static class Near
{
    public static void Equal(double[] expected, double[] actual, double tolerance, string what)
    {
        var scale = Math.Max(1, expected.Max(Math.Abs));
        for (var i = 0; i < expected.Length; i++)
            Assert.True(Math.Abs(expected[i] - actual[i]) <= tolerance * scale,
                $"{what}: component {i} is {actual[i]:R}, expected {expected[i]:R} (tolerance {tolerance * scale:E1})");
    }

    public static void Equal(TwistablePoint expected, TwistablePoint actual, double tolerance, string what) =>
        Equal([expected.x, expected.y, expected.z], [actual.x, actual.y, actual.z], tolerance, what);

    public static void Equal(TwistableVector expected, TwistableVector actual, double tolerance, string what) =>
        Equal([expected.x, expected.y, expected.z], [actual.x, actual.y, actual.z], tolerance, what);

    public static void Equal(TwistableBivector expected, TwistableBivector actual, double tolerance, string what) =>
        Equal([expected.xy, expected.yz, expected.zx], [actual.xy, actual.yz, actual.zx], tolerance, what);

    /// <summary>Central difference of f at x with step h, component-wise.</summary>
    public static TwistableVector Difference(Func<double, TwistablePoint> f, double x, double h = 1e-5)
    {
        var (a, b) = (f(x + h), f(x - h));
        return new((a.x - b.x) / (2 * h), (a.y - b.y) / (2 * h), (a.z - b.z) / (2 * h));
    }

    public static TwistableVector Cross(TwistableVector a, TwistableVector b) =>
        new(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);

    public static double Dot(TwistableVector a, TwistableVector b) => a.x * b.x + a.y * b.y + a.z * b.z;
}
