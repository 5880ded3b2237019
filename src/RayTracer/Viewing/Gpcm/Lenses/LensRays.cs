using System.Runtime.CompilerServices;
using RayTracer.Maths;

namespace RayTracer.Viewing;

/// <summary>
/// A catalogue lens's unit ray direction for a view-plane point: the view plane mapped straight to the
/// kernel's parameters (the (u, v) of <see cref="Gpcm.RectangularMap"/> or <see cref="Gpcm.PolarMap"/>
/// folded into the surface's own angles and lengths), then the lens's generated kernel.
/// </summary>
internal static class LensRays
{
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Rectangle(RectangularProjectionSurface rectangle, Point2D pp, ViewPlane vp, GpcmOrientation orientation) =>
        LensKernels.Rectangle(
            pp.x * (rectangle.Width / (vp.HorizontalResolution * vp.PixelSize)),
            pp.y * (rectangle.Height / (vp.VerticalResolution * vp.PixelSize)),
            rectangle.Distance, orientation);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Sphere(SphereLens sphere, Point2D pp, ViewPlane vp, GpcmOrientation orientation) =>
        LensKernels.Sphere(
            pp.x * (2 * sphere.MaxAzimuth / (vp.HorizontalResolution * vp.PixelSize)),
            pp.y * (2 * sphere.MaxElevation / (vp.VerticalResolution * vp.PixelSize)),
            orientation);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Cylinder(CylinderLens cylinder, Point2D pp, ViewPlane vp, GpcmOrientation orientation) =>
        LensKernels.Ring(
            pp.x * (2 * cylinder.MaxAzimuth / (vp.HorizontalResolution * vp.PixelSize)),
            pp.y * (cylinder.Height / (vp.VerticalResolution * vp.PixelSize)),
            1, orientation);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Cone(ConeLens cone, Point2D pp, ViewPlane vp, GpcmOrientation orientation)
    {
        var along = pp.y * (cone.Slant / (vp.VerticalResolution * vp.PixelSize));
        return LensKernels.Ring(
            pp.x * (2 * cone.MaxAzimuth / (vp.HorizontalResolution * vp.PixelSize)),
            along * cone.CosTilt, 1 - along * cone.SinTilt, orientation);
    }

    /// <summary>False outside the ellipse inscribed in the image.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Cap(CapLens cap, Point2D pp, ViewPlane vp, GpcmOrientation orientation, out Vector3D direction)
    {
        var nx = 2 * pp.x / (vp.HorizontalResolution * vp.PixelSize);
        var ny = 2 * pp.y / (vp.VerticalResolution * vp.PixelSize);
        var r = Math.Sqrt(nx * nx + ny * ny);
        if (r > 1)
        {
            direction = default;
            return false;
        }
        // The polar angle's cosine and sine are the image point's x/r and y/r: no atan2 to undo.
        direction = r > 0
            ? LensKernels.Cap(nx / r, ny / r, r * cap.MaxAngleFromAxis, orientation)
            : LensKernels.Cap(1, 0, 0, orientation);
        return true;
    }
}
