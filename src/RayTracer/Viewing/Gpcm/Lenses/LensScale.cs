namespace RayTracer.Viewing;

/// <summary>
/// What a lens multiplies view-plane coordinates by to get its kernel's parameters, for one view plane
/// (its resolution and pixel size): the (u, v) map and the surface's own spans folded into one factor
/// per axis, so a ray pays a multiplication where the map divided. Immutable: a camera swaps in a new
/// one when the view plane changes.
/// </summary>
internal sealed class LensScale
{
    private readonly ViewPlane _plane;
    private readonly int _width;
    private readonly int _height;
    private readonly double _pixelSize;

    private LensScale(ViewPlane plane, double x, double y, double z = 0)
    {
        _plane = plane;
        _width = plane.HorizontalResolution;
        _height = plane.VerticalResolution;
        _pixelSize = plane.PixelSize;
        X = x;
        Y = y;
        Z = z;
    }

    /// <summary>Per unit of view-plane x: the rectangle's x or the azimuth; for the polar map, the half width it divides by.</summary>
    public double X { get; }

    /// <summary>Per unit of view-plane y: the rectangle's y, the elevation or a length up the surface; for the polar map, the half height it divides by.</summary>
    public double Y { get; }

    /// <summary>The rectangle's distance ahead (the pinhole reads all it needs from here).</summary>
    public double Z { get; }

    public bool Fits(ViewPlane vp) =>
        ReferenceEquals(vp, _plane) && vp.HorizontalResolution == _width && vp.VerticalResolution == _height && vp.PixelSize == _pixelSize;

    /// <summary>The factors of a lens that has a kernel (see <see cref="GpcmLensKinds.Of"/>).</summary>
    public static LensScale For(object surface, ViewPlane vp)
    {
        var width = vp.HorizontalResolution * vp.PixelSize;
        var height = vp.VerticalResolution * vp.PixelSize;
        return surface switch
        {
            RectangularProjectionSurface r => new(vp, r.Width / width, r.Height / height, r.Distance),
            SphereLens s => new(vp, 2 * s.MaxAzimuth / width, 2 * s.MaxElevation / height),
            CylinderLens c => new(vp, 2 * c.MaxAzimuth / width, c.Height / height),
            ConeLens c => new(vp, 2 * c.MaxAzimuth / width, c.Slant / height),
            CapLens => new(vp, width / 2, height / 2),
            _ => throw new ArgumentException($"No lens kernel for {surface.GetType().Name}.", nameof(surface)),
        };
    }
}
