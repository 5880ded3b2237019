using Twister;

namespace Twister.Tests;

/// <summary>Every catalogue curve against its textbook equation and the derivative of that equation.</summary>
public sealed class CurveCatalogueTests
{
    private const double Tau = 2 * Math.PI;

    /// <summary>A catalogue curve with its closed form U(t) and U'(t), written from the curve's definition.</summary>
    public sealed record Case(string Name, TwistCurve Curve, Func<double, TwistablePoint> Point, Func<double, TwistableVector> Tangent)
    {
        public override string ToString() => Name;
    }

    public static TheoryData<Case> Cases()
    {
        var data = new TheoryData<Case>();
        data.Add(new("line segment", TwistCurves.LineSegment(new(1, 2, 3), new(-2, 0.5, 4)),
            t => new(1 - 3 * t, 2 - 1.5 * t, 3 + t), _ => new(-3, -1.5, 1)));
        data.Add(new("circle (6.5)", TwistCurves.Circle(new(0.5, -1, 2), 1.5),
            t => new(0.5 + 1.5 * Math.Cos(Tau * t), -1 + 1.5 * Math.Sin(Tau * t), 2),
            t => new(-1.5 * Tau * Math.Sin(Tau * t), 1.5 * Tau * Math.Cos(Tau * t), 0)));
        data.Add(new("arc", TwistCurves.Arc(new(1, 1, 0), 2, 0.3, 2.0),
            t => new(1 + 2 * Math.Cos(0.3 + 2 * t), 1 + 2 * Math.Sin(0.3 + 2 * t), 0),
            t => new(-4 * Math.Sin(0.3 + 2 * t), 4 * Math.Cos(0.3 + 2 * t), 0)));
        data.Add(new("helix (6.6)", TwistCurves.Helix(0.7, 3),
            t => new(0.7 * Math.Cos(3 * Tau * t), 0.7 * Math.Sin(3 * Tau * t), t),
            t => new(-0.7 * 3 * Tau * Math.Sin(3 * Tau * t), 0.7 * 3 * Tau * Math.Cos(3 * Tau * t), 1)));
        data.Add(new("conical helix", TwistCurves.ConicalHelix(1, 0.2, 4, 2.5),
            t => new((1 - 0.8 * t) * Math.Cos(4 * Tau * t), (1 - 0.8 * t) * Math.Sin(4 * Tau * t), 2.5 * t),
            t => new(-0.8 * Math.Cos(4 * Tau * t) - (1 - 0.8 * t) * 4 * Tau * Math.Sin(4 * Tau * t),
                -0.8 * Math.Sin(4 * Tau * t) + (1 - 0.8 * t) * 4 * Tau * Math.Cos(4 * Tau * t), 2.5)));
        data.Add(new("trochoid", TwistCurves.Trochoid(0.5, 0.8, 2),
            t => new(0.5 * 2 * Tau * t - 0.8 * Math.Sin(2 * Tau * t), 0.5 - 0.8 * Math.Cos(2 * Tau * t), 0),
            t => new(2 * Tau * (0.5 - 0.8 * Math.Cos(2 * Tau * t)), 2 * Tau * 0.8 * Math.Sin(2 * Tau * t), 0)));
        data.Add(Roulette("epitrochoid", TwistCurves.Epitrochoid(3, 1, 0.5, 1), 4, -0.5, 4));
        data.Add(Roulette("hypotrochoid", TwistCurves.Hypotrochoid(5, 3, 5, 3), 2, 5, -2.0 / 3));
        data.Add(new("rose", TwistCurves.Rose(2, 5.0 / 3, 3), t => RosePoint(2, 5.0 / 3, 3 * Tau * t), t => RoseTangent(2, 5.0 / 3, 3 * Tau, t)));
        return data;
    }

    /// <summary>c (cos φ, sin φ) + d (cos kφ, sin kφ), φ = 2π turns t.</summary>
    private static Case Roulette(string name, TwistCurve curve, double c, double d, double k)
    {
        var w = Tau * (name == "hypotrochoid" ? 3 : 1);
        return new(name, curve,
            t => new(c * Math.Cos(w * t) + d * Math.Cos(k * w * t), c * Math.Sin(w * t) + d * Math.Sin(k * w * t), 0),
            t => new(-w * (c * Math.Sin(w * t) + d * k * Math.Sin(k * w * t)), w * (c * Math.Cos(w * t) + d * k * Math.Cos(k * w * t)), 0));
    }

    private static TwistablePoint RosePoint(double a, double k, double phi) =>
        new(a * Math.Cos(k * phi) * Math.Cos(phi), a * Math.Cos(k * phi) * Math.Sin(phi), 0);

    private static TwistableVector RoseTangent(double a, double k, double w, double t)
    {
        var phi = w * t;
        var rho = a * Math.Cos(k * phi);
        var rhoPrime = -a * k * Math.Sin(k * phi);
        return new(w * (rhoPrime * Math.Cos(phi) - rho * Math.Sin(phi)), w * (rhoPrime * Math.Sin(phi) + rho * Math.Cos(phi)), 0);
    }

    private static double[] RandomParameters(int seed)
    {
        var random = new Random(seed);
        return [.. Enumerable.Range(0, 25).Select(_ => random.NextDouble())];
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Points_equal_the_closed_form(Case c)
    {
        foreach (var t in RandomParameters(1))
            Near.Equal(c.Point(t), c.Curve.PointAt(t), 1e-12, $"{c.Name} at t = {t}");
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Tangents_equal_the_closed_form_derivative(Case c)
    {
        foreach (var t in RandomParameters(2))
            Near.Equal(c.Tangent(t), c.Curve.TangentAt(t), 1e-12, $"{c.Name} tangent at t = {t}");
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void Tangents_equal_central_differences(Case c)
    {
        foreach (var t in RandomParameters(3))
            Near.Equal(Near.Difference(c.Curve.PointAt, t), c.Curve.TangentAt(t), 1e-6, $"{c.Name} tangent at t = {t}");
    }
}
