using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Viewing;

/// <summary>Perspective projection from the eye through a view plane at distance <see cref="ViewDistance"/>.</summary>
public sealed class PinholeCamera : Camera
{
    /// <summary>Distance from the eye to the view plane; with the pixel size it fixes the field of view.</summary>
    public double ViewDistance { get; set; } = 500;

    /// <summary>Magnification: larger values narrow the field of view.</summary>
    public double Zoom { get; set; } = 1.0;

    /// <summary>Sets the view distance so the image width spans <paramref name="degrees"/> horizontally.</summary>
    public void SetHorizontalFieldOfView(double degrees, ViewPlane vp) =>
        ViewDistance = 0.5 * vp.HorizontalResolution * vp.PixelSize / Math.Tan(MathConstants.ToRadians(degrees) / 2) * Zoom;

    public Vector3D RayDirection(Point2D pp)
    {
        var d = pp.x / Zoom * U + pp.y / Zoom * V - ViewDistance * W;
        return d.Normalized();
    }

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        ray = new Ray(Eye, RayDirection(pp));
        return true;
    }
}
