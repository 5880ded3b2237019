namespace Twister;

/// <summary>
/// A twist's parameter map f(u, v) (thesis §6.4.1): the constants 0, 1, −1, the parameters u and v,
/// any affine a·u + b·v + c, or a function of the caller's own. Tangents and normals need ∂f/∂u and
/// ∂f/∂v, so a function comes with both (<see cref="Of"/>).
/// </summary>
public sealed class ParameterMap
{
    private readonly Func<double, double, double>? _function, _byU, _byV;

    private ParameterMap(double a, double b, double c, Func<double, double, double>? function = null,
        Func<double, double, double>? byU = null, Func<double, double, double>? byV = null)
    {
        A = a;
        B = b;
        C = c;
        _function = function;
        _byU = byU;
        _byV = byV;
    }

    public static ParameterMap Zero { get; } = new(0, 0, 0);
    public static ParameterMap One { get; } = new(0, 0, 1);
    public static ParameterMap MinusOne { get; } = new(0, 0, -1);
    public static ParameterMap U { get; } = new(1, 0, 0);
    public static ParameterMap V { get; } = new(0, 1, 0);

    /// <summary>The affine coefficients; zero for a user function.</summary>
    public double A { get; }
    public double B { get; }
    public double C { get; }

    public bool IsAffine => _function is null;

    /// <summary>True when the map does not change with v (what a curve's twists need).</summary>
    public bool IgnoresV => _function is null ? B == 0 : _byV is null;

    /// <summary>f(u, v) = a·u + b·v + c.</summary>
    public static ParameterMap Affine(double a, double b, double c)
    {
        Require.Finite(a, nameof(a));
        Require.Finite(b, nameof(b));
        Require.Finite(c, nameof(c));
        return new(a, b, c);
    }

    /// <summary>
    /// Any function of (u, v) with its two partial derivatives; <paramref name="ignoresV"/> says that
    /// f does not depend on v, which lets the map drive a curve.
    /// </summary>
    public static ParameterMap Of(Func<double, double, double> function, Func<double, double, double> derivativeU,
        Func<double, double, double> derivativeV)
    {
        ArgumentNullException.ThrowIfNull(function);
        ArgumentNullException.ThrowIfNull(derivativeU);
        ArgumentNullException.ThrowIfNull(derivativeV);
        return new(0, 0, 0, function, derivativeU, derivativeV);
    }

    /// <summary>A function of u alone, with its derivative: usable by curves.</summary>
    public static ParameterMap OfU(Func<double, double> function, Func<double, double> derivative)
    {
        ArgumentNullException.ThrowIfNull(function);
        ArgumentNullException.ThrowIfNull(derivative);
        return new(0, 0, 0, (u, _) => function(u), (u, _) => derivative(u), null);
    }

    public double Evaluate(double u, double v) =>
        _function is null ? A * u + B * v + C : Checked(_function(u, v), "f", u, v);

    public double DerivativeU(double u, double v) => _byU is null ? A : Checked(_byU(u, v), "∂f/∂u", u, v);

    public double DerivativeV(double u, double v) =>
        _function is null ? B : _byV is null ? 0 : Checked(_byV(u, v), "∂f/∂v", u, v);

    private static double Checked(double value, string what, double u, double v) => double.IsFinite(value)
        ? value
        : throw new ArgumentException(FormattableString.Invariant($"the parameter map's {what} is {value} at (u, v) = ({u}, {v}); it must be finite"), nameof(u));
}
