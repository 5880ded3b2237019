using RayTracer.Maths;
using RayTracer.Transforms;
using RayTracer.Viewing;

namespace RayTracer.Geometry.Instancing;

/// <summary>
/// x ↦ t + s R(x): a rotation about the origin, a uniform scale, then a translation (thesis §6.6.1),
/// in the twelve coefficients of a TSR instance: the translation (3), the rotation's unit axis and
/// angle (4), the scale (1) and four ray-independent auxiliaries, cos φ / s, sin φ / s,
/// (1 − cos φ) / s and 1 / s. The generated ray and normal kernels use the first three auxiliaries;
/// the fourth completes the layout and serves <see cref="ToLocal"/>.
/// </summary>
public readonly struct TsrTransform
{
    // Relative tolerance of the frame analysis: the lengths of the two vectors and their dot product.
    private const double FrameTolerance = 1e-9;

    public readonly double tx, ty, tz;
    public readonly double kx, ky, kz, angle;
    public readonly double scale;
    public readonly double cosOverScale, sinOverScale, versineOverScale, inverseScale;

    private TsrTransform(Vector3D translation, Vector3D unitAxis, double radians, double factor)
    {
        tx = translation.x;
        ty = translation.y;
        tz = translation.z;
        kx = unitAxis.x;
        ky = unitAxis.y;
        kz = unitAxis.z;
        angle = radians;
        scale = factor;
        inverseScale = 1 / factor;
        var (sin, cos) = Math.SinCos(radians);
        cosOverScale = cos * inverseScale;
        sinOverScale = sin * inverseScale;
        versineOverScale = (1 - cos) * inverseScale;
    }

    public static TsrTransform Identity { get; } = new(Vector3D.Zero, Vector3D.UnitY, 0, 1);

    public Vector3D Translation => new(tx, ty, tz);

    public Vector3D Axis => new(kx, ky, kz);

    /// <summary>From the parts directly: <paramref name="axis"/> need not be unit, <paramref name="factor"/> must be positive.</summary>
    public static TsrTransform FromParts(Vector3D translation, Vector3D axis, double radians, double factor)
    {
        if (!IsFinite(translation) || !IsFinite(axis) || !double.IsFinite(radians))
            throw new ArgumentException("A TSR transform needs a finite translation, axis and angle.");
        if (!(factor > 0) || !double.IsFinite(factor))
            throw new ArgumentOutOfRangeException(nameof(factor), factor, "A TSR scale must be a finite number above 0.");
        var length = axis.Length;
        if (!(length > 0))
            throw new ArgumentException("The rotation axis of a TSR transform must not be the zero vector.", nameof(axis));
        return new(translation, axis / length, radians, factor);
    }

    /// <summary>
    /// Reads the transform that took e1, e2 and the origin to the frame's Vx, Vy and origin: the
    /// rotor taking e1 onto Vx̂, then the one taking the turned e2 onto Vŷ, composed as in (6.14),
    /// from the generated kernels. Throws when the frame is singular or not a rotation with a
    /// uniform scale.
    /// </summary>
    public static TsrTransform FromFrame(FrameOfReference frame)
    {
        var vx = new Vector3D(frame.Vx.x, frame.Vx.y, frame.Vx.z);
        var vy = new Vector3D(frame.Vy.x, frame.Vy.y, frame.Vy.z);
        var origin = new Vector3D(frame.Origin.x, frame.Origin.y, frame.Origin.z);
        if (!IsFinite(vx) || !IsFinite(vy) || !IsFinite(origin))
            throw new ArgumentException($"The frame of reference has a non-finite coefficient: Vx {vx}, Vy {vy}, origin {origin}.", nameof(frame));
        var sx = vx.Length;
        var sy = vy.Length;
        if (!(sx > 0) || !(sy > 0))
            throw new ArgumentException($"The frame of reference is singular: Vx {vx} and Vy {vy} must both be non-zero.", nameof(frame));
        var cross = Vector3D.Cross(vx, vy).Length;
        if (!(cross > FrameTolerance * sx * sy))
            throw new ArgumentException($"The frame of reference is singular: Vx {vx} and Vy {vy} are parallel.", nameof(frame));
        if (Math.Abs(sx - sy) > FrameTolerance * Math.Max(sx, sy))
            throw new ArgumentException(
                $"A TSR instance needs a uniform scale, but the frame scales x by {sx} and y by {sy}; use a matrix Instance for non-uniform scales.",
                nameof(frame));
        if (Math.Abs(Vector3D.Dot(vx, vy)) > FrameTolerance * sx * sy)
            throw new ArgumentException(
                $"A TSR instance needs a rotation, but Vx {vx} and Vy {vy} are not perpendicular (a shear); use a matrix Instance.",
                nameof(frame));

        var ux = vx / sx;
        var uy = vy / sy;
        var rx = RotorOntoOrHalfTurn(Vector3D.UnitX, ux, Vector3D.UnitZ);
        OrientationKernels.Axes(rx, out _, out var turnedY, out _);
        var ry = RotorOntoOrHalfTurn(turnedY, uy, ux);
        var rotor = OrientationKernels.Compose(ry, rx);
        var (axis, radians) = InstancingKernels.AxisAngle(rotor);
        return new(origin, axis, radians, 0.5 * (sx + sy));
    }

    /// <summary>t + s R(p), with Rodrigues' formula; used for bounds, not per ray.</summary>
    public Point3D ToWorld(Point3D p)
    {
        var x = (Vector3D)p;
        var k = Axis;
        var (sin, cos) = Math.SinCos(angle);
        var turned = cos * x + sin * Vector3D.Cross(k, x) + (1 - cos) * Vector3D.Dot(k, x) * k;
        return new Point3D(tx, ty, tz) + scale * turned;
    }

    /// <summary>(1/s) R⁻¹(p − t): where a world point sits in the object's own frame.</summary>
    public Point3D ToLocal(Point3D p)
    {
        var q = new Vector3D(p.x - tx, p.y - ty, p.z - tz);
        var k = Axis;
        var turned = cosOverScale * q - sinOverScale * Vector3D.Cross(k, q) + versineOverScale * Vector3D.Dot(k, q) * k;
        return new Point3D(turned.x, turned.y, turned.z);
    }

    // The rotor taking unit a onto unit b; when b = −a, the half turn about the unit `perpendicular` (⟂ a).
    private static Rotor3D RotorOntoOrHalfTurn(Vector3D a, Vector3D b, Vector3D perpendicular)
    {
        if (Vector3D.Dot(a, b) > -1 + Tolerances.RelativeRounding)
            return OrientationKernels.RotorOnto(a, b);
        var axis = perpendicular - Vector3D.Dot(perpendicular, a) * a;
        return OrientationKernels.HalfTurn(axis.Normalized());
    }

    private static bool IsFinite(Vector3D v) => double.IsFinite(v.x) && double.IsFinite(v.y) && double.IsFinite(v.z);
}
