using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>
/// Spherical panorama: x maps linearly to azimuth λ in [-λmax, λmax] and y to elevation ψ in [-ψmax, ψmax];
/// with 180° and 90° the image covers the whole sphere of directions.
/// </summary>
public sealed class SphericalCamera : Camera
{
    public double MaxLambdaDegrees { get; set; } = 180;
    public double MaxPsiDegrees { get; set; } = 90;

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        var nx = 2.0 / (vp.PixelSize * vp.HorizontalResolution) * pp.x;
        var ny = 2.0 / (vp.PixelSize * vp.VerticalResolution) * pp.y;
        var lambda = nx * MathConstants.ToRadians(MaxLambdaDegrees);
        var psi = ny * MathConstants.ToRadians(MaxPsiDegrees);
        // Azimuth measured from -w (straight ahead), elevation from the u-w plane.
        var d = Math.Cos(psi) * Math.Sin(lambda) * U + Math.Sin(psi) * V - Math.Cos(psi) * Math.Cos(lambda) * W;
        ray = new Ray(Eye, d);
        return true;
    }
}
