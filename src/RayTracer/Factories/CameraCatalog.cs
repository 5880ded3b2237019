using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using RayTracer.Viewing;

namespace RayTracer.Factories;

/// <summary>
/// The cameras a scene can be seen through from the command line (<c>--camera NAME[:DEGREES]</c>): the
/// generalized pinhole cameras of thesis §6.5, one projection surface each, and the hand-derived
/// cameras they reproduce. Panoramas give the image's vertical extent the horizontal's angular
/// resolution, so pixels cover square arcs whatever the image size.
/// </summary>
public static class CameraCatalog
{
    public static IReadOnlyList<CameraChoice> All { get; } =
    [
        new("rectangular", "generalized pinhole camera, flat rectangle: the classic perspective view", 60, 180, false,
            (degrees, vp) => Gpcm.Rectangular(degrees, vp)),
        new("cylindrical", "generalized pinhole camera, (part) cylinder about image-up: a cylindrical panorama", 360, 360, true,
            (degrees, vp) => Gpcm.Cylindrical(degrees, vp)),
        new("conic", "generalized pinhole camera, (part) cone about image-up narrowing upwards: a conic panorama", 360, 360, true,
            (degrees, vp) => Gpcm.Conic(degrees, vp)),
        new("spherical", "generalized pinhole camera, (part) sphere: azimuth across, elevation up", 360, 360, true,
            (degrees, vp) => Gpcm.Spherical(degrees, SphericalElevation(degrees, vp))),
        new("fisheye", "generalized pinhole camera, sphere cap with the polar mapping: an equidistant fisheye", 180, 360, true,
            (degrees, _) => Gpcm.Fisheye(degrees)),
        new("pinhole", "hand-derived perspective camera (same rays as rectangular)", 60, 180, false,
            (degrees, vp) =>
            {
                var camera = new PinholeCamera();
                camera.SetHorizontalFieldOfView(degrees, vp);
                return camera;
            }),
        new("spherical-hand", "hand-derived spherical panorama (same rays as spherical)", 360, 360, true,
            (degrees, vp) => new SphericalCamera { MaxLambdaDegrees = degrees / 2, MaxPsiDegrees = SphericalElevation(degrees, vp) / 2 }),
        new("fisheye-hand", "hand-derived equidistant fisheye (same rays as fisheye)", 180, 360, true,
            (degrees, _) => new FisheyeCamera { MaxPsiDegrees = degrees / 2 }),
    ];

    public static IEnumerable<string> Names => All.Select(c => c.Name);

    public static bool TryFind(string name, [NotNullWhen(true)] out CameraChoice? choice)
    {
        choice = All.FirstOrDefault(c => string.Equals(c.Name, name, StringComparison.OrdinalIgnoreCase));
        return choice is not null;
    }

    /// <summary>
    /// Reads <c>NAME</c> or <c>NAME:DEGREES</c>. On failure <paramref name="error"/> says what is wrong:
    /// an unknown name, a field of view that is not a number, or one out of the camera's range.
    /// </summary>
    public static bool TryParse(string text, [NotNullWhen(true)] out CameraChoice? choice, out double degrees, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(text);
        var colon = text.IndexOf(':');
        var name = colon < 0 ? text : text[..colon];
        degrees = 0;
        error = null;
        if (!TryFind(name, out choice))
        {
            error = $"unknown camera '{name}'; the cameras are {string.Join(", ", Names)} (see 'raytracer list')";
            return false;
        }

        if (colon < 0)
        {
            degrees = choice.DefaultDegrees;
            return true;
        }

        var angle = text[(colon + 1)..];
        if (!double.TryParse(angle, NumberStyles.Float, CultureInfo.InvariantCulture, out degrees) || !double.IsFinite(degrees))
            error = $"camera '{choice.Name}': the field of view '{angle}' is not a number of degrees";
        else if (!choice.Accepts(degrees))
            error = string.Create(CultureInfo.InvariantCulture, $"camera '{choice.Name}': the field of view must be {choice.RangeText}, not {degrees}°");
        if (error is null)
            return true;
        choice = null;
        return false;
    }

    /// <summary>The elevation span (degrees) that gives a spherical panorama square pixels: at most 180°.</summary>
    public static double SphericalElevation(double horizontalDegrees, ViewPlane vp) =>
        Math.Min(180, horizontalDegrees * vp.VerticalResolution / vp.HorizontalResolution);
}
