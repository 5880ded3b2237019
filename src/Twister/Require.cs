namespace Twister;

/// <summary>Checks of user input: a bad value fails here with its name instead of turning into NaN later.</summary>
internal static class Require
{
    public static void Finite(double value, string name)
    {
        if (!double.IsFinite(value))
            throw new ArgumentException(FormattableString.Invariant($"'{name}' must be a finite number, not {value}"), name);
    }

    public static void Finite(TwistablePoint p, string name)
    {
        if (!double.IsFinite(p.x) || !double.IsFinite(p.y) || !double.IsFinite(p.z))
            throw new ArgumentException($"'{name}' must have finite coordinates, not {p}", name);
    }

    public static void Finite(TwistableVector d, string name)
    {
        if (!double.IsFinite(d.x) || !double.IsFinite(d.y) || !double.IsFinite(d.z))
            throw new ArgumentException($"'{name}' must have finite coordinates, not {d}", name);
    }

    public static void Parameters(double u, double v)
    {
        Finite(u, nameof(u));
        Finite(v, nameof(v));
    }

    public static void NotNull(object? value, string name) => ArgumentNullException.ThrowIfNull(value, name);

    /// <summary>A unit vector along <paramref name="d"/>, from the generated UnitDirection kernel.</summary>
    public static TwistableVector UnitDirection(TwistableVector d, string name)
    {
        Finite(d, name);
        var unit = new TwistableVector();

        #region GMac : UnitDirection
        //GMac.Bind("a", "Vector3D", d);
        //GMac.Bind("u", "Vector3D", unit);
        double tmp0 = 1.0 / Math.Sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        unit.x = d.x * tmp0;
        unit.y = d.y * tmp0;
        unit.z = d.z * tmp0;
        #endregion

        if (!double.IsFinite(unit.x) || !double.IsFinite(unit.y) || !double.IsFinite(unit.z))
            throw new ArgumentException($"'{name}' must not have zero length, got {d}", name);
        return unit;
    }
}
