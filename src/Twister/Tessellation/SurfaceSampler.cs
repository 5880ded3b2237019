namespace Twister.Tessellation;

/// <summary>
/// Evaluates a surface for tessellation: rejects non-finite values with the parameters where they
/// appeared, and gives a unit normal also where the surface's own normal vanishes (poles, apexes).
/// </summary>
internal sealed class SurfaceSampler(IParametricSurface surface)
{
    // Offsets in (u, v) for the normals around a singular point: small enough to stay close, and a
    // larger second try for surfaces that are singular along a whole strip.
    private static readonly double[] InsetSteps = [1e-4, 1e-2];

    /// <summary>Typical length of the raw normal; shorter than a billionth of it counts as vanished.</summary>
    public double NormalScale { get; set; }

    public TwistablePoint Point(double u, double v)
    {
        var p = surface.PointAt(u, v);
        if (!Geometry3.IsFinite(p))
        {
            throw new TessellationException(FormattableString.Invariant($"The surface has a non-finite point {p} at (u, v) = ({u}, {v})."));
        }

        return p;
    }

    public TwistableVector RawNormal(double u, double v)
    {
        var n = surface.NormalAt(u, v);
        if (!Geometry3.IsFinite(n))
        {
            throw new TessellationException(FormattableString.Invariant($"The surface has a non-finite normal {n} at (u, v) = ({u}, {v})."));
        }

        return n;
    }

    public TwistableVector UnitNormal(double u, double v)
    {
        if (TryUnit(RawNormal(u, v), 1e-9 * NormalScale, out var unit))
        {
            return unit;
        }

        foreach (var step in InsetSteps)
        {
            var sum = new TwistableVector(0, 0, 0);
            foreach (var (du, dv) in new[] { (-step, -step), (step, -step), (step, step), (-step, step) })
            {
                if (TryUnit(RawNormal(Math.Clamp(u + du, 0, 1), Math.Clamp(v + dv, 0, 1)), 1e-9 * NormalScale, out var n))
                {
                    sum = new TwistableVector(sum.x + n.x, sum.y + n.y, sum.z + n.z);
                }
            }

            // Unit normals that cancel out (a cone's apex seen from all sides) give no direction either.
            if (TryUnit(sum, 1e-6, out unit))
            {
                return unit;
            }
        }

        throw new TessellationException(FormattableString.Invariant($"The surface normal vanishes everywhere around (u, v) = ({u}, {v}); the surface is degenerate there."));
    }

    public static TwistableVector Average(IEnumerable<TwistableVector> normals)
    {
        var sum = new TwistableVector(0, 0, 0);
        foreach (var n in normals)
        {
            sum = new TwistableVector(sum.x + n.x, sum.y + n.y, sum.z + n.z);
        }

        var length = Geometry3.Length(sum);
        return length > 0 ? new TwistableVector(sum.x / length, sum.y / length, sum.z / length) : new TwistableVector(0, 0, 1);
    }

    private static bool TryUnit(TwistableVector n, double threshold, out TwistableVector unit)
    {
        var length = Geometry3.Length(n);
        if (length > threshold && length > 0)
        {
            unit = new TwistableVector(n.x / length, n.y / length, n.z / length);
            return true;
        }

        unit = default;
        return false;
    }
}
