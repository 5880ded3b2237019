namespace Twister;

/// <summary>
/// The curve catalogue (thesis §6.2.2, §6.4.2, Figures 6-7 to 6-10), each built from twists only.
/// Curves lie in the x-y plane (helixes rise along z); move them with <see cref="TwistCascade.TransformedBy"/>.
/// </summary>
public static class TwistCurves
{
    private static readonly TwistableVector X = new(1, 0, 0), Y = new(0, 1, 0), Z = new(0, 0, 1);

    /// <summary>From <paramref name="start"/> to <paramref name="end"/>: a translation by u (end − start).</summary>
    public static TwistCurve LineSegment(TwistablePoint start, TwistablePoint end) =>
        new(start, TwistCascade.Empty.Translate(new(end.x - start.x, end.y - start.y, end.z - start.z), 1, ParameterMap.U));

    /// <summary>(6.5) c + r (cos 2πu, sin 2πu, 0): translate c by r along x, rotate about the z axis through c.</summary>
    public static TwistCurve Circle(TwistablePoint centre, double radius) => Arc(centre, radius, 0, 2 * Math.PI);

    /// <summary>c + r (cos φ, sin φ, 0) for φ from <paramref name="startAngle"/> over <paramref name="sweep"/> radians.</summary>
    public static TwistCurve Arc(TwistablePoint centre, double radius, double startAngle, double sweep)
    {
        Require.Finite(radius, nameof(radius));
        Require.Finite(startAngle, nameof(startAngle));
        Require.Finite(sweep, nameof(sweep));
        var cascade = TwistCascade.Empty
            .Translate(X, radius, ParameterMap.One)
            .RotateAbout(Z, centre, 1, ParameterMap.Affine(sweep, 0, startAngle));
        return new(centre, cascade);
    }

    /// <summary>(6.6) (r cos 2πku, r sin 2πku, h u): translate by r along x, rotate about z by 2πku, translate by h u along z.</summary>
    public static TwistCurve Helix(double radius, double turns, double height = 1) => ConicalHelix(radius, radius, turns, height);

    /// <summary>A helix whose radius runs linearly from <paramref name="startRadius"/> to <paramref name="endRadius"/>.</summary>
    public static TwistCurve ConicalHelix(double startRadius, double endRadius, double turns, double height)
    {
        Require.Finite(startRadius, nameof(startRadius));
        Require.Finite(endRadius, nameof(endRadius));
        Require.Finite(turns, nameof(turns));
        Require.Finite(height, nameof(height));
        var cascade = TwistCascade.Empty
            .Translate(X, startRadius, ParameterMap.One)
            .Translate(X, endRadius - startRadius, ParameterMap.U)
            .RotateAboutZ(2 * Math.PI * turns, ParameterMap.U)
            .Translate(Z, height, ParameterMap.U);
        return new(default, cascade);
    }

    /// <summary>
    /// A circle of radius r rolling on the x axis, pen at distance d from its centre, over
    /// <paramref name="turns"/> turns: (r φ − d sin φ, r − d cos φ), φ = 2π turns u.
    /// </summary>
    public static TwistCurve Trochoid(double rollingRadius, double penDistance, double turns)
    {
        Require.Finite(rollingRadius, nameof(rollingRadius));
        Require.Finite(penDistance, nameof(penDistance));
        Require.Finite(turns, nameof(turns));
        var angle = 2 * Math.PI * turns;
        var cascade = TwistCascade.Empty
            .RotateAbout(Z, new(0, rollingRadius, 0), -angle, ParameterMap.U)
            .Translate(X, rollingRadius * angle, ParameterMap.U);
        return new(new(0, rollingRadius - penDistance, 0), cascade);
    }

    /// <summary>
    /// A circle of radius r rolling outside a fixed circle of radius R about the origin, pen at d from
    /// its centre: ((R + r) cos φ − d cos((R + r) φ / r), (R + r) sin φ − d sin((R + r) φ / r)), φ = 2π turns u.
    /// </summary>
    public static TwistCurve Epitrochoid(double fixedRadius, double rollingRadius, double penDistance, double turns) =>
        Roulette(fixedRadius + rollingRadius, fixedRadius / rollingRadius, -penDistance, turns, nameof(rollingRadius), rollingRadius);

    /// <summary>
    /// A circle of radius r rolling inside a fixed circle of radius R: ((R − r) cos φ + d cos((R − r) φ / r),
    /// (R − r) sin φ − d sin((R − r) φ / r)), φ = 2π turns u.
    /// </summary>
    public static TwistCurve Hypotrochoid(double fixedRadius, double rollingRadius, double penDistance, double turns) =>
        Roulette(fixedRadius - rollingRadius, -fixedRadius / rollingRadius, penDistance, turns, nameof(rollingRadius), rollingRadius);

    /// <summary>
    /// The rose ρ = a cos(k φ), φ = 2π turns u: a point a/2 from a centre that circles the origin at
    /// a/2 with rate 1 − k while the point circles the centre at rate 2k.
    /// </summary>
    public static TwistCurve Rose(double amplitude, double k, double turns)
    {
        Require.Finite(amplitude, nameof(amplitude));
        Require.Finite(k, nameof(k));
        Require.Finite(turns, nameof(turns));
        var angle = 2 * Math.PI * turns;
        var cascade = TwistCascade.Empty
            .RotateAbout(Z, new(amplitude / 2, 0, 0), 2 * k * angle, ParameterMap.U)
            .RotateAboutZ((1 - k) * angle, ParameterMap.U);
        return new(new(amplitude, 0, 0), cascade);
    }

    /// <summary>
    /// The centre at distance <paramref name="centreDistance"/> circles the origin by φ while the pen,
    /// <paramref name="offset"/> from the centre along x at u = 0, turns about the centre by
    /// <paramref name="rate"/> φ more.
    /// </summary>
    private static TwistCurve Roulette(double centreDistance, double rate, double offset, double turns, string radiusName, double radius)
    {
        Require.Finite(radius, radiusName);
        if (radius == 0) throw new ArgumentException($"'{radiusName}' must not be zero", radiusName);
        Require.Finite(centreDistance, "fixedRadius");
        Require.Finite(offset, "penDistance");
        Require.Finite(turns, nameof(turns));
        var angle = 2 * Math.PI * turns;
        var cascade = TwistCascade.Empty
            .RotateAbout(Z, new(centreDistance, 0, 0), rate * angle, ParameterMap.U)
            .RotateAboutZ(angle, ParameterMap.U);
        return new(new(centreDistance + offset, 0, 0), cascade);
    }

    internal static TwistableVector AxisX => X;
    internal static TwistableVector AxisY => Y;
    internal static TwistableVector AxisZ => Z;
}
