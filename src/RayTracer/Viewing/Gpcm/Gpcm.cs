using RayTracer.Maths;
using RayTracer.Tracing;
using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// The generalized pinhole camera (thesis §6.5): rays leave the eye through the points of a projection
/// surface S(u, v), given in the camera's rest frame (eye at the origin, looking along −e3, e2 up) and
/// turned into the world by <see cref="GpcmOrientation"/>. The view plane maps to (u, v) ∈ [0, 1]²
/// rectangularly: u across the image width from the left edge, v up the height from the bottom edge.
/// </summary>
public sealed class Gpcm(IParametricSurface surface) : Camera
{
    public IParametricSurface Surface { get; } = surface ?? throw new ArgumentNullException(nameof(surface));

    /// <summary>The orientation from the last <see cref="Orient"/>; null before.</summary>
    public GpcmOrientation? Orientation { get; private set; }

    /// <summary>A rectangular surface spanning <paramref name="horizontalDegrees"/> across the image: the classic pinhole.</summary>
    public static Gpcm Rectangular(double horizontalDegrees, ViewPlane vp)
    {
        if (!(horizontalDegrees > 0 && horizontalDegrees < 180))
            throw new ArgumentOutOfRangeException(nameof(horizontalDegrees), $"A rectangular camera's field of view must be between 0° and 180°, not {horizontalDegrees}°.");
        var width = vp.HorizontalResolution * vp.PixelSize;
        var height = vp.VerticalResolution * vp.PixelSize;
        var distance = 0.5 * width / Math.Tan(MathConstants.ToRadians(horizontalDegrees) / 2);
        return new Gpcm(new RectangularProjectionSurface(width, height, distance));
    }

    /// <summary>Orients the camera from <see cref="Camera.Eye"/>, <see cref="Camera.LookAt"/> and <see cref="Camera.Up"/>; call after changing them.</summary>
    public GpcmOrientation Orient() => Orientation = GpcmOrientation.LookingAt(Eye, LookAt, Up);

    /// <summary>The surface parameters of view-plane point <paramref name="pp"/>.</summary>
    public static (double u, double v) RectangularMap(Point2D pp, ViewPlane vp) =>
        (pp.x / (vp.HorizontalResolution * vp.PixelSize) + 0.5, pp.y / (vp.VerticalResolution * vp.PixelSize) + 0.5);

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        var orientation = Orientation ?? throw new InvalidOperationException("The camera is not oriented: call Orient() after setting its eye, look-at point and up direction.");
        var (u, v) = RectangularMap(pp, vp);
        var s = Surface.PointAt(u, v);
        ray = new Ray(orientation.Eye, orientation.ToWorld(new Vector3D(s.x, s.y, s.z)).Normalized());
        return true;
    }
}
