using System.Runtime.CompilerServices;
using RayTracer.Maths;

namespace RayTracer.Viewing;

/// <summary>
/// A catalogue lens's unit ray direction for a view-plane point: the point scaled to the kernel's
/// parameters (<see cref="LensScale"/>: the (u, v) of <see cref="Gpcm.RectangularMap"/> or
/// <see cref="Gpcm.PolarMap"/> folded into the surface's own angles and lengths), then the lens's
/// generated kernel.
/// </summary>
internal static class LensRays
{
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Sphere(Point2D pp, LensScale scale, GpcmOrientation orientation) =>
        LensKernels.Sphere(pp.x * scale.X, pp.y * scale.Y, orientation);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Cylinder(Point2D pp, LensScale scale, GpcmOrientation orientation) =>
        LensKernels.Ring(pp.x * scale.X, pp.y * scale.Y, 1, orientation);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3D Cone(ConeLens cone, Point2D pp, LensScale scale, GpcmOrientation orientation)
    {
        var along = pp.y * scale.Y;
        return LensKernels.Ring(pp.x * scale.X, along * cone.CosTilt, 1 - along * cone.SinTilt, orientation);
    }

    /// <summary>False outside the ellipse inscribed in the image.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Cap(CapLens cap, Point2D pp, LensScale scale, GpcmOrientation orientation, out Vector3D direction)
    {
        // Divided, not multiplied by a reciprocal, so the ellipse's edge falls where the polar map puts it.
        var nx = pp.x / scale.X;
        var ny = pp.y / scale.Y;
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
