using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// A projection surface of the camera catalogue: a Twister surface that also keeps the few numbers
/// its shape was built from. With them a <see cref="Gpcm"/> takes each ray from the lens's generated
/// kernel (view-plane map, surface and turn into the world composed in one macro) instead of
/// evaluating the cascade and turning its point; both give the same rays.
/// </summary>
public abstract class GpcmLens : IParametricSurface
{
    private protected GpcmLens(SingleTwistSurface twistSurface) => TwistSurface = twistSurface;

    /// <summary>The surface as a Twister cascade applied to a seed point.</summary>
    public SingleTwistSurface TwistSurface { get; }

    public TwistablePoint PointAt(double u, double v) => TwistSurface.PointAt(u, v);

    public TwistableVector NormalAt(double u, double v) => TwistSurface.NormalAt(u, v);

    /// <summary>S(u, v) without the parameter checks: for the camera, whose u and v come from finite view-plane points.</summary>
    internal TwistablePoint RestPoint(double u, double v)
    {
        var s = TwistSurface;
        return s.Cascade.Apply(s.Seed, s.UStart + u * (s.UEnd - s.UStart), s.VStart + v * (s.VEnd - s.VStart));
    }
}
