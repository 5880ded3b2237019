namespace Twister.Tests.Tessellation.Shapes;

/// <summary>A curve from its closed form and derivative.</summary>
internal sealed class ClosedFormCurve(string name, Func<double, TwistablePoint> point, Func<double, TwistableVector> tangent) : IParametricCurve
{
    public static ClosedFormCurve Circle(double r) => new(
        "circle",
        t => new(r * Math.Cos(2 * Math.PI * t), r * Math.Sin(2 * Math.PI * t), 0),
        t => new(-2 * Math.PI * r * Math.Sin(2 * Math.PI * t), 2 * Math.PI * r * Math.Cos(2 * Math.PI * t), 0));

    /// <summary>Three turns of radius r rising by <paramref name="height"/>.</summary>
    public static ClosedFormCurve Helix(double r, double height) => new(
        "helix",
        t => new(r * Math.Cos(6 * Math.PI * t), r * Math.Sin(6 * Math.PI * t), height * t),
        t => new(-6 * Math.PI * r * Math.Sin(6 * Math.PI * t), 6 * Math.PI * r * Math.Cos(6 * Math.PI * t), height));

    /// <summary>Four-petal rose ρ = cos 2θ, θ = 2πt.</summary>
    public static ClosedFormCurve Rose() => new(
        "rose",
        t =>
        {
            var a = 2 * Math.PI * t;
            return new(Math.Cos(2 * a) * Math.Cos(a), Math.Cos(2 * a) * Math.Sin(a), 0);
        },
        t =>
        {
            var a = 2 * Math.PI * t;
            double rho = Math.Cos(2 * a), drho = -2 * Math.Sin(2 * a);
            return new(2 * Math.PI * (drho * Math.Cos(a) - rho * Math.Sin(a)), 2 * Math.PI * (drho * Math.Sin(a) + rho * Math.Cos(a)), 0);
        });

    public static ClosedFormCurve ByName(string name) => name switch
    {
        "circle" => Circle(1),
        "helix" => Helix(0.5, 2),
        "rose" => Rose(),
        _ => throw new ArgumentException(name),
    };

    public TwistablePoint PointAt(double t) => point(t);

    public TwistableVector TangentAt(double t) => tangent(t);

    public override string ToString() => name;
}
