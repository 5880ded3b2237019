using System.Runtime.CompilerServices;
using RayTracer.Maths;
using RayTracer.Tracing;
using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// The generalized pinhole camera (thesis §6.5): rays leave the eye through the points of a projection
/// surface S(u, v), given in the camera's rest frame (eye at the origin, looking along −e3, e2 up) and
/// turned into the world by <see cref="GpcmOrientation"/>. The view plane maps to (u, v) ∈ [0, 1]²
/// rectangularly or polarly (<see cref="GpcmMapping"/>).
/// </summary>
public sealed class Gpcm(IParametricSurface surface, GpcmMapping mapping = GpcmMapping.Rectangular) : Camera
{
    public IParametricSurface Surface { get; } = surface ?? throw new ArgumentNullException(nameof(surface));

    public GpcmMapping Mapping { get; } = Enum.IsDefined(mapping)
        ? mapping
        : throw new ArgumentOutOfRangeException(nameof(mapping), $"Unknown uv mapping {mapping}.");

    /// <summary>Rays start at the eye (default) or on the surface (a cutting surface, thesis §6.5.3).</summary>
    public GpcmRayOrigin RayOrigin
    {
        get => _rayOrigin;
        set
        {
            _rayOrigin = value;
            _activeLens = ActiveLens();
        }
    }

    private GpcmRayOrigin _rayOrigin = GpcmRayOrigin.Eye;

    /// <summary>Rays run from the eye through the surface (default) or back from the surface through the eye.</summary>
    public GpcmRayDirection RayDirection { get; set; } = GpcmRayDirection.Outward;

    /// <summary>
    /// World length of one rest-frame unit of the surface. Directions do not depend on it; it places the
    /// surface, and so the start of rays with <see cref="GpcmRayOrigin.Surface"/>.
    /// </summary>
    public double SurfaceScale
    {
        get => _surfaceScale;
        set => _surfaceScale = value > 0 && double.IsFinite(value)
            ? value
            : throw new ArgumentOutOfRangeException(nameof(SurfaceScale), $"The surface scale must be a positive finite number, not {value}.");
    }

    private double _surfaceScale = 1;

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

    /// <summary>
    /// A spherical panorama spanning <paramref name="horizontalDegrees"/> of azimuth (up to 360) and
    /// <paramref name="verticalDegrees"/> of elevation (up to 180), centred on the look direction.
    /// </summary>
    public static Gpcm Spherical(double horizontalDegrees, double verticalDegrees)
    {
        RequireFieldOfView(horizontalDegrees, 360, "A spherical camera's horizontal", nameof(horizontalDegrees));
        RequireFieldOfView(verticalDegrees, 180, "A spherical camera's vertical", nameof(verticalDegrees));
        return new Gpcm(GpcmSurfaces.Sphere(MathConstants.ToRadians(horizontalDegrees) / 2, MathConstants.ToRadians(verticalDegrees) / 2));
    }

    /// <summary>A spherical panorama with half as much elevation as azimuth (360° gives the whole sphere on a 2:1 image).</summary>
    public static Gpcm Spherical(double horizontalDegrees)
    {
        RequireFieldOfView(horizontalDegrees, 360, "A spherical camera's", nameof(horizontalDegrees));
        return Spherical(horizontalDegrees, horizontalDegrees / 2);
    }

    /// <summary>
    /// A cylindrical panorama spanning <paramref name="horizontalDegrees"/> of azimuth (up to 360) on the
    /// unit cylinder about image-up; its height keeps the image's aspect on the unrolled cylinder, so
    /// pixels cover equal arcs and heights.
    /// </summary>
    public static Gpcm Cylindrical(double horizontalDegrees, ViewPlane vp)
    {
        RequireFieldOfView(horizontalDegrees, 360, "A cylindrical camera's", nameof(horizontalDegrees));
        var arc = MathConstants.ToRadians(horizontalDegrees);
        return new Gpcm(GpcmSurfaces.Cylinder(arc / 2, arc * vp.VerticalResolution / vp.HorizontalResolution));
    }

    /// <summary>
    /// A conic panorama spanning <paramref name="horizontalDegrees"/> of azimuth (up to 360) on a cone
    /// about image-up whose generatrix leans <paramref name="tiltDegrees"/> towards the axis (default 30°:
    /// the cone narrows upwards). Its middle ring is the unit circle and its slant keeps the image's aspect
    /// there, as the cylinder's height does, up to where the cone's narrow end is a fifth of the middle
    /// ring (a taller image then stretches rows); a tilt of 0° is the cylindrical panorama.
    /// </summary>
    public static Gpcm Conic(double horizontalDegrees, ViewPlane vp, double tiltDegrees = 30)
    {
        RequireFieldOfView(horizontalDegrees, 360, "A conic camera's", nameof(horizontalDegrees));
        var arc = MathConstants.ToRadians(horizontalDegrees);
        var tilt = MathConstants.ToRadians(tiltDegrees);
        // A tall image would take the cone through its apex: stop where the narrow end keeps a fifth of
        // the middle ring's radius, as the spherical panorama stops at the poles.
        var slant = arc * vp.VerticalResolution / vp.HorizontalResolution;
        var sine = Math.Abs(Math.Sin(tilt));
        if (sine > 0)
            slant = Math.Min(slant, 1.6 / sine);
        return new Gpcm(GpcmSurfaces.Cone(arc / 2, slant, tilt));
    }

    /// <summary>
    /// An equidistant fisheye seeing <paramref name="degrees"/> across (up to 360; 180 is the hemisphere)
    /// on the ellipse inscribed in the image, through a sphere cap with the polar mapping.
    /// </summary>
    public static Gpcm Fisheye(double degrees)
    {
        RequireFieldOfView(degrees, 360, "A fisheye camera's", nameof(degrees));
        return new Gpcm(GpcmSurfaces.Cap(MathConstants.ToRadians(degrees) / 2), GpcmMapping.Polar);
    }

    private static void RequireFieldOfView(double degrees, double most, string what, string name)
    {
        if (!(degrees > 0 && degrees <= most))
            throw new ArgumentOutOfRangeException(name, $"{what} field of view must be more than 0° and at most {most}°, not {degrees}°.");
    }

    /// <summary>Orients the camera from <see cref="Camera.Eye"/>, <see cref="Camera.LookAt"/> and <see cref="Camera.Up"/>; call after changing them.</summary>
    public GpcmOrientation Orient() => Orientation = GpcmOrientation.LookingAt(Eye, LookAt, Up);

    public override void Aim() => Orient();

    /// <summary>
    /// The projection surface where the camera stands (scaled by <see cref="SurfaceScale"/>, turned and
    /// moved to the eye): where rays from the surface start, and what a scene draws to show the camera.
    /// </summary>
    public IParametricSurface PlacedSurface() =>
        new GpcmPlacedSurface(Surface, Orientation ?? throw new InvalidOperationException("The camera is not oriented: call Orient() first."), _surfaceScale);

    /// <summary>The surface parameters of view-plane point <paramref name="pp"/>.</summary>
    public static (double u, double v) RectangularMap(Point2D pp, ViewPlane vp) =>
        (pp.x / (vp.HorizontalResolution * vp.PixelSize) + 0.5, pp.y / (vp.VerticalResolution * vp.PixelSize) + 0.5);

    /// <summary>
    /// The surface parameters of view-plane point <paramref name="pp"/> under the polar mapping; false
    /// outside the ellipse inscribed in the image.
    /// </summary>
    public static bool PolarMap(Point2D pp, ViewPlane vp, out double u, out double v)
    {
        var nx = 2 * pp.x / (vp.HorizontalResolution * vp.PixelSize);
        var ny = 2 * pp.y / (vp.VerticalResolution * vp.PixelSize);
        v = Math.Sqrt(nx * nx + ny * ny);
        var turns = Math.Atan2(ny, nx) / (2 * Math.PI);
        u = turns < 0 ? turns + 1 : turns;
        return v <= 1;
    }

    /// <summary>
    /// False (the default): the catalogue's lenses take each ray from their generated kernel. True: every
    /// ray goes the general way any surface takes (the surface's cascade, then the turn into the world),
    /// which gives the same rays more slowly: a reference for checking the kernels.
    /// </summary>
    public bool EvaluateThroughCascade
    {
        get => _evaluateThroughCascade;
        set
        {
            _evaluateThroughCascade = value;
            _activeLens = ActiveLens();
        }
    }

    private bool _evaluateThroughCascade;

    /// <summary>
    /// S(u, v), calling the catalogue's sealed surface types directly so the JIT can inline them (the
    /// same points as <see cref="IParametricSurface.PointAt"/>; u and v come from finite view-plane
    /// coordinates, so their checks are skipped).
    /// </summary>
    private TwistablePoint SurfacePoint(double u, double v) => Surface switch
    {
        GpcmLens lens => lens.RestPoint(u, v),
        SingleTwistSurface twisted => twisted.Cascade.Apply(twisted.Seed,
            twisted.UStart + u * (twisted.UEnd - twisted.UStart), twisted.VStart + v * (twisted.VEnd - twisted.VStart)),
        RectangularProjectionSurface rectangle => rectangle.PointAt(u, v),
        _ => Surface.PointAt(u, v),
    };

    private readonly GpcmLensKind _lens = GpcmLensKinds.Of(surface, mapping);

    /// <summary>The lens kernel rays take now: none when rays start on the surface or go through the cascade.</summary>
    private GpcmLensKind _activeLens = GpcmLensKinds.Of(surface, mapping);

    private GpcmLensKind ActiveLens() => RayOrigin == GpcmRayOrigin.Eye && !EvaluateThroughCascade ? _lens : GpcmLensKind.None;

    /// <summary>The lens's view-plane scales for the last view plane; replaced whole, so render threads share it safely.</summary>
    private LensScale? _scale;

    public override bool GetRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        // The pinhole's lens is the cheapest, so anything else on its path (a call, the other lenses'
        // code, the registers they save) is a large share of its cost: it alone is handled here, and
        // every other case, first use of a view plane and error included, goes to one call.
        var orientation = Orientation;
        var scale = _scale;
        if (_activeLens == GpcmLensKind.Rectangle && orientation is not null && scale is not null && scale.Fits(vp))
            return FromEye(LensKernels.Rectangle(pp.x * scale.X, pp.y * scale.Y, scale.Z, orientation), orientation, out ray);
        return OtherRay(pp, vp, out ray);
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private bool OtherRay(Point2D pp, ViewPlane vp, out Ray ray)
    {
        var orientation = Orientation ?? throw new InvalidOperationException("The camera is not oriented: call Orient() after setting its eye, look-at point and up direction.");
        var lens = _activeLens;
        if (lens == GpcmLensKind.None)
            return CascadeRay(pp, vp, orientation, out ray);
        var scale = _scale;
        if (scale is null || !scale.Fits(vp))
            _scale = scale = LensScale.For(Surface, vp);
        return lens switch
        {
            GpcmLensKind.Rectangle => FromEye(LensKernels.Rectangle(pp.x * scale.X, pp.y * scale.Y, scale.Z, orientation), orientation, out ray),
            GpcmLensKind.Sphere => FromEye(LensRays.Sphere(pp, scale, orientation), orientation, out ray),
            GpcmLensKind.Cylinder => FromEye(LensRays.Cylinder(pp, scale, orientation), orientation, out ray),
            GpcmLensKind.Cone => FromEye(LensRays.Cone((ConeLens)Surface, pp, scale, orientation), orientation, out ray),
            _ => CapRay(pp, scale, orientation, out ray),
        };
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private bool FromEye(Vector3D direction, GpcmOrientation orientation, out Ray ray)
    {
        // Field by field, and the negation written out: an operator call or a whole-struct copy here
        // made the JIT keep the direction in memory, which cost the pinhole a third of its time.
        ray.o = orientation.Eye;
        ray.d = RayDirection == GpcmRayDirection.Inward ? new Vector3D(-direction.x, -direction.y, -direction.z) : direction;
        ray.tMin = MathConstants.Epsilon;
        return true;
    }

    private bool CapRay(Point2D pp, LensScale scale, GpcmOrientation orientation, out Ray ray)
    {
        if (LensRays.Cap((CapLens)Surface, pp, scale, orientation, out var direction))
            return FromEye(direction, orientation, out ray);
        ray = default;
        return false;
    }

    /// <summary>The general way: the surface point in the rest frame, turned into the world.</summary>
    private bool CascadeRay(Point2D pp, ViewPlane vp, GpcmOrientation orientation, out Ray ray)
    {
        double u, v;
        if (Mapping == GpcmMapping.Rectangular)
            (u, v) = RectangularMap(pp, vp);
        else if (!PolarMap(pp, vp, out u, out v))
        {
            ray = default;
            return false;
        }
        var s = SurfacePoint(u, v);
        var toSurface = orientation.ToWorld(new Vector3D(s.x, s.y, s.z));
        var direction = toSurface.Normalized();
        if (RayDirection == GpcmRayDirection.Inward)
            direction = -direction;
        var origin = RayOrigin == GpcmRayOrigin.Eye ? orientation.Eye : orientation.Eye + _surfaceScale * toSurface;
        ray = new Ray(origin, direction);
        return true;
    }
}
