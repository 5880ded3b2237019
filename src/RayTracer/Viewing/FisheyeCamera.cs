using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>
/// Equidistant fisheye: the angle ψ from the view axis grows linearly with the distance from the image centre,
/// reaching <see cref="MaxPsiDegrees"/> on the inscribed circle; outside the circle nothing is seen.
/// </summary>
public sealed class FisheyeCamera : Camera
{
    /// <summary>Half of the field of view, in degrees (90 gives a hemispherical view).</summary>
    public double MaxPsiDegrees { get; set; } = 90;

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        var nx = 2.0 / (vp.PixelSize * vp.HorizontalResolution) * pp.x;
        var ny = 2.0 / (vp.PixelSize * vp.VerticalResolution) * pp.y;
        var r2 = nx * nx + ny * ny;
        if (r2 > 1.0)
        {
            ray = default;
            return false;
        }
        var r = Math.Sqrt(r2);
        var psi = r * MathConstants.ToRadians(MaxPsiDegrees);
        double cosAlpha = r > 0 ? nx / r : 1, sinAlpha = r > 0 ? ny / r : 0;
        var sinPsi = Math.Sin(psi);
        var d = sinPsi * cosAlpha * U + sinPsi * sinAlpha * V - Math.Cos(psi) * W;
        ray = new Ray(Eye, d);
        return true;
    }
}
