using RayTracer.Maths;

namespace RayTracer.Viewing;

/// <summary>
/// Where a generalized pinhole camera stands and looks (thesis §6.5, Figure 6-14). At rest the camera
/// sits at the origin looking along −e3 with e2 up. It is turned so its up axis is the given up
/// direction, then about that up axis so it looks along the look-at direction projected on the ground
/// plane (perpendicular to up), then in the vertical plane onto the look-at direction itself, and
/// moved to the eye. Looking straight along ±up (no ground-plane projection) skips the turn about up:
/// the heading is then the one the first step left, and image-up is that heading reversed or kept.
/// </summary>
public sealed class GpcmOrientation
{
    /// <summary>A ground-plane projection shorter than this (of a unit look direction) counts as none.</summary>
    public const double VerticalTolerance = 1e-12;

    private GpcmOrientation(Point3D eye, Rotor3D rotor)
    {
        Eye = eye;
        Rotor = rotor;
        OrientationKernels.Axes(rotor, out var right, out var up, out var back);
        Right = right;
        Up = up;
        Back = back;
    }

    public Point3D Eye { get; }

    /// <summary>The unit rotor taking the camera at rest to its orientation.</summary>
    public Rotor3D Rotor { get; }

    /// <summary>Image right (the image of e1).</summary>
    public Vector3D Right { get; }

    /// <summary>Image up (the image of e2).</summary>
    public Vector3D Up { get; }

    /// <summary>Opposite of the look direction (the image of e3).</summary>
    public Vector3D Back { get; }

    /// <summary>The direction of rest-frame vector <paramref name="d"/> once the camera is turned.</summary>
    public Vector3D ToWorld(Vector3D d) => d.x * Right + d.y * Up + d.z * Back;

    /// <summary>Orients a camera at <paramref name="eye"/> looking at <paramref name="lookAt"/> with the given up direction (any length but zero).</summary>
    public static GpcmOrientation LookingAt(Point3D eye, Point3D lookAt, Vector3D up)
    {
        Validate(eye, lookAt, up);
        var d = (lookAt - eye).Normalized();
        var n = up.Normalized();

        // Stand the camera up: e2 onto up. A half turn about e1 when up is −e2.
        var stand = RotorOnto(Vector3D.UnitY, n, Vector3D.UnitX);
        OrientationKernels.Axes(stand, out _, out _, out var back);
        var heading = -back;

        // Turn about up to the ground-plane projection of the look direction: both lie in the ground
        // plane, so up is a fallback axis that keeps the turn about up when they are opposite.
        var ground = OrientationKernels.Rejection(d, n);
        var turn = Rotor3D.Identity;
        if (ground.Length > VerticalTolerance)
        {
            var p = ground.Normalized();
            turn = RotorOnto(heading, p, n);
            heading = p;
        }

        // Tilt in the vertical plane onto the look direction: at most a quarter turn, never opposite.
        var tilt = OrientationKernels.RotorOnto(heading, d);
        var rotor = OrientationKernels.Compose(tilt, OrientationKernels.Compose(turn, stand));
        return new GpcmOrientation(eye, rotor);
    }

    /// <summary>
    /// Throws <see cref="ArgumentException"/> unless the eye and the look-at point are distinct finite
    /// points and the up direction is a nonzero finite vector: what any camera needs to be oriented.
    /// </summary>
    public static void Validate(Point3D eye, Point3D lookAt, Vector3D up)
    {
        var look = lookAt - eye;
        if (!(look.LengthSquared > 0) || !double.IsFinite(look.LengthSquared))
            throw new ArgumentException($"The eye {eye} and the look-at point {lookAt} must be distinct finite points.", nameof(lookAt));
        if (!(up.LengthSquared > 0) || !double.IsFinite(up.LengthSquared))
            throw new ArgumentException($"The up direction {up} must be a nonzero finite vector.", nameof(up));
    }

    /// <summary>
    /// The rotor taking unit a onto unit b. For opposite-leaning vectors (a·b &lt; 0) it is a half turn
    /// about <paramref name="fallbackAxis"/> (unit, perpendicular to a), taking a to −a, followed by
    /// the rotation of −a onto b: well conditioned however close b is to −a, exactly the half turn for
    /// b = −a, and the shortest rotation whenever the fallback axis is perpendicular to b too.
    /// </summary>
    public static Rotor3D RotorOnto(Vector3D a, Vector3D b, Vector3D fallbackAxis)
    {
        if (a.Dot(b) >= 0)
            return OrientationKernels.RotorOnto(a, b);
        return OrientationKernels.Compose(OrientationKernels.RotorOnto(-a, b), OrientationKernels.HalfTurn(fallbackAxis));
    }
}
