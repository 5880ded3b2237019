using Twister;

namespace RayTracer.Geometry.Parametric;

/// <summary>
/// A line of constant u or constant v on a parametric surface, t running over the other parameter:
/// with <see cref="CurveTube"/>, the wires of a surface drawn as a cage. Tangents are central
/// differences, good enough to sample the curve for drawing.
/// </summary>
public sealed class IsoParameterCurve : IParametricCurve
{
    private const double Step = 1e-6;
    private readonly IParametricSurface _surface;

    private IsoParameterCurve(IParametricSurface surface, bool alongU, double fixedParameter)
    {
        ArgumentNullException.ThrowIfNull(surface);
        if (!(fixedParameter >= 0 && fixedParameter <= 1))
            throw new ArgumentOutOfRangeException(nameof(fixedParameter), fixedParameter, "A surface parameter lies in [0, 1].");
        _surface = surface;
        AlongU = alongU;
        FixedParameter = fixedParameter;
    }

    /// <summary>The curve v = <paramref name="v"/>, t = u.</summary>
    public static IsoParameterCurve AtV(IParametricSurface surface, double v) => new(surface, true, v);

    /// <summary>The curve u = <paramref name="u"/>, t = v.</summary>
    public static IsoParameterCurve AtU(IParametricSurface surface, double u) => new(surface, false, u);

    /// <summary>True when t runs over u (v fixed).</summary>
    public bool AlongU { get; }

    public double FixedParameter { get; }

    public TwistablePoint PointAt(double t) => AlongU ? _surface.PointAt(t, FixedParameter) : _surface.PointAt(FixedParameter, t);

    public TwistableVector TangentAt(double t)
    {
        var (a, b) = (Math.Max(0, t - Step), Math.Min(1, t + Step));
        var (p, q) = (PointAt(a), PointAt(b));
        var h = b - a;
        return new((q.x - p.x) / h, (q.y - p.y) / h, (q.z - p.z) / h);
    }
}
