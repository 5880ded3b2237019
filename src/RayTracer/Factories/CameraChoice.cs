using System.Globalization;
using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Factories;

/// <summary>
/// One camera of the catalogue: its command-line name, what it is, the field of view it accepts and a
/// way to build it, oriented, for an eye, a look-at point, an up direction and a view plane.
/// </summary>
public sealed class CameraChoice
{
    private readonly Func<double, ViewPlane, Camera> _create;

    internal CameraChoice(string name, string description, double defaultDegrees, double mostDegrees, bool mostIncluded,
        Func<double, ViewPlane, Camera> create)
    {
        Name = name;
        Description = description;
        DefaultDegrees = defaultDegrees;
        MostDegrees = mostDegrees;
        MostIncluded = mostIncluded;
        _create = create;
    }

    public string Name { get; }
    public string Description { get; }

    /// <summary>The field of view used when none is given, in degrees.</summary>
    public double DefaultDegrees { get; }

    /// <summary>The widest field of view accepted, in degrees (see <see cref="MostIncluded"/>).</summary>
    public double MostDegrees { get; }

    /// <summary>Whether <see cref="MostDegrees"/> itself is accepted (360° is; a rectangle's 180° is not).</summary>
    public bool MostIncluded { get; }

    /// <summary>The accepted range as the messages print it, e.g. "more than 0° and at most 360°".</summary>
    public string RangeText => string.Create(CultureInfo.InvariantCulture,
        $"more than 0° and {(MostIncluded ? "at most" : "less than")} {MostDegrees}°");

    public bool Accepts(double degrees) => degrees > 0 && (MostIncluded ? degrees <= MostDegrees : degrees < MostDegrees);

    /// <summary>
    /// The camera with field of view <paramref name="degrees"/>, standing at <paramref name="eye"/>,
    /// looking at <paramref name="lookAt"/> with image-up towards <paramref name="up"/>. Throws
    /// <see cref="ArgumentException"/> with a message for a field of view out of range, coinciding eye and
    /// look-at point, or a zero up direction.
    /// </summary>
    public Camera Create(double degrees, ViewPlane vp, Point3D eye, Point3D lookAt, Vector3D up)
    {
        ArgumentNullException.ThrowIfNull(vp);
        if (!Accepts(degrees))
            throw new ArgumentOutOfRangeException(nameof(degrees), string.Create(CultureInfo.InvariantCulture,
                $"The {Name} camera's field of view must be {RangeText}, not {degrees}°."));
        // Both camera families check the same way, so the hand cameras get the GPCM's messages too.
        GpcmOrientation.Validate(eye, lookAt, up);
        var camera = _create(degrees, vp);
        camera.Eye = eye;
        camera.LookAt = lookAt;
        camera.Up = up;
        camera.Aim();
        return camera;
    }
}
