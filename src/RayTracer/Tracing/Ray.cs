using RayTracer.Maths;

namespace RayTracer.Tracing;

/// <summary>
/// A ray o + t d, for t above <see cref="tMin"/>. The direction is not required to be unit length.
/// </summary>
public struct Ray
{
    public Point3D o;
    public Vector3D d;

    /// <summary>
    /// Hits at t up to this are ignored: a ray leaving a surface must not hit that surface again through
    /// rounding ("shadow acne"). It is a length in the units of <see cref="d"/>, so it must follow the
    /// scene's size (<see cref="Scenes.World.RayEpsilon"/>): a fixed one hides every surface of a tiny scene.
    /// </summary>
    public double tMin;

    public Ray(Point3D origin, Vector3D direction, double minDistance = MathConstants.Epsilon)
    {
        o = origin;
        d = direction;
        tMin = minDistance;
    }

    public readonly Point3D At(double t) => new(o.x + t * d.x, o.y + t * d.y, o.z + t * d.z);

    public override readonly string ToString() => $"{o} + t{d}";
}
