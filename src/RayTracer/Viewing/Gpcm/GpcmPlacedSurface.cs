using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// A camera's projection surface where the camera stands: the rest-frame surface scaled by
/// <see cref="Gpcm.SurfaceScale"/>, turned by the orientation and moved to the eye. Rays with
/// <see cref="GpcmRayOrigin.Surface"/> start on it; scenes draw it to show the camera's layout.
/// </summary>
internal sealed class GpcmPlacedSurface(IParametricSurface rest, GpcmOrientation orientation, double scale) : IParametricSurface
{
    public TwistablePoint PointAt(double u, double v)
    {
        var p = rest.PointAt(u, v);
        var w = orientation.Eye + scale * orientation.ToWorld(new(p.x, p.y, p.z));
        return new(w.x, w.y, w.z);
    }

    /// <summary>Turned like the surface; scaling multiplies the tangent plane by scale², a positive factor.</summary>
    public TwistableVector NormalAt(double u, double v)
    {
        var n = rest.NormalAt(u, v);
        var w = orientation.ToWorld(new(scale * scale * n.x, scale * scale * n.y, scale * scale * n.z));
        return new(w.x, w.y, w.z);
    }
}
