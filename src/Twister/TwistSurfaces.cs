namespace Twister;

/// <summary>
/// The surface catalogue (thesis §6.3.2, §6.4.3, Figures 6-1, 6-11, 6-12), each built from twists only.
/// Parameters are oriented so that the normal ∂S/∂u ^ ∂S/∂v ⌋ I3⁻¹ points outward on the closed
/// surfaces and away from the axis on the others.
/// </summary>
public static class TwistSurfaces
{
    private static readonly TwistableVector X = TwistCurves.AxisX, Y = TwistCurves.AxisY, Z = TwistCurves.AxisZ;

    /// <summary>
    /// (6.11) translate c by r along z, rotate about the x axis through c by πu, then about the z axis
    /// through c by 2πv: c + r (sin πu sin 2πv, −sin πu cos 2πv, cos πu) (the printed (6.11) turns the
    /// other way about z).
    /// </summary>
    public static SingleTwistSurface Sphere(TwistablePoint centre, double radius)
    {
        Require.Finite(radius, nameof(radius));
        var cascade = TwistCascade.Empty
            .Translate(Z, radius, ParameterMap.One)
            .RotateAbout(X, centre, Math.PI, ParameterMap.U)
            .RotateAbout(Z, centre, 2 * Math.PI, ParameterMap.V);
        return new(centre, cascade);
    }

    /// <summary>
    /// Figure 6-1, first: a helix (radius r, <paramref name="turns"/> turns, height h) in u swept about
    /// the z axis in v: (r cos 2π(k u − v), r sin 2π(k u − v), h u). v turns clockwise so the normal points out.
    /// </summary>
    public static SingleTwistSurface HelixCylinder(double radius, double height, double turns)
    {
        var helix = TwistCurves.Helix(radius, turns, height);
        return new(helix.Seed, helix.Cascade.RotateAboutZ(-2 * Math.PI, ParameterMap.V));
    }

    /// <summary>
    /// Figure 6-1, second: a circle in u translated along z by h v: (r cos 2πu, r sin 2πu, h v). (The
    /// thesis says "along y", which would sweep a flat band; the cylinder about z needs z.)
    /// </summary>
    public static SingleTwistSurface CircleCylinder(double radius, double height)
    {
        Require.Finite(height, nameof(height));
        var circle = TwistCurves.Circle(default, radius);
        return new(circle.Seed, circle.Cascade.Translate(Z, height, ParameterMap.V));
    }

    /// <summary>
    /// A cone: the base circle of radius r at z = 0 rolled to the apex (0, 0, h):
    /// (1 − v) r (cos 2πu, sin 2πu, 0) + v (0, 0, h).
    /// </summary>
    public static RolledTwistSurface Cone(double radius, double height)
    {
        Require.Finite(height, nameof(height));
        var apex = new TwistCurve(new(0, 0, height), TwistCascade.Empty);
        return new(TwistCurves.Circle(default, radius), apex);
    }

    /// <summary>
    /// A torus about the z axis: the tube circle (radius r about (R, 0, 0), turned about the y axis by
    /// 2πu) swept about z by 2πv: ((R + r cos 2πu) cos 2πv, (R + r cos 2πu) sin 2πv, −r sin 2πu).
    /// </summary>
    public static SingleTwistSurface Torus(double majorRadius, double minorRadius)
    {
        Require.Finite(majorRadius, nameof(majorRadius));
        Require.Finite(minorRadius, nameof(minorRadius));
        var cascade = TwistCascade.Empty
            .RotateAbout(Y, new(majorRadius, 0, 0), 2 * Math.PI, ParameterMap.U)
            .RotateAboutZ(2 * Math.PI, ParameterMap.V);
        return new(new(majorRadius + minorRadius, 0, 0), cascade);
    }

    /// <summary>
    /// A helicoid: the segment from (−r, 0, 0) to (r, 0, 0) in u, twisted about the z axis by a full twist
    /// of 2π turns v and slide h v: ((2u − 1) r cos 2πkv, (2u − 1) r sin 2πkv, h v).
    /// </summary>
    public static SingleTwistSurface Helicoid(double radius, double height, double turns)
    {
        Require.Finite(radius, nameof(radius));
        Require.Finite(turns, nameof(turns));
        Require.Finite(height, nameof(height));
        var cascade = TwistCascade.Empty
            .Translate(X, 2 * radius, ParameterMap.U)
            .Then(new FullTwist(Z, default, 2 * Math.PI * turns, ParameterMap.V, height, ParameterMap.V));
        return new(new(-radius, 0, 0), cascade);
    }

    /// <summary>
    /// Any curve in u (over its own parameter range) turned about the line through
    /// <paramref name="origin"/> along <paramref name="axis"/> by −2πv: the normal points away from the
    /// axis where the profile runs along +axis.
    /// </summary>
    public static SingleTwistSurface Revolution(TwistCurve profile, TwistableVector axis, TwistablePoint origin)
    {
        Require.NotNull(profile, nameof(profile));
        var cascade = profile.Cascade.RotateAbout(axis, origin, -2 * Math.PI, ParameterMap.V);
        return new(profile.Seed, cascade, profile.UStart, profile.UEnd);
    }

    /// <summary>
    /// A twisted column: a cross-section curve of the x-y plane (counter-clockwise for an outward normal)
    /// lifted along z by h v while it turns about z by <paramref name="twistAngle"/> v, a full twist.
    /// </summary>
    public static SingleTwistSurface TwistedColumn(TwistCurve crossSection, double height, double twistAngle)
    {
        Require.NotNull(crossSection, nameof(crossSection));
        Require.Finite(height, nameof(height));
        Require.Finite(twistAngle, nameof(twistAngle));
        var cascade = crossSection.Cascade.Then(new FullTwist(Z, default, twistAngle, ParameterMap.V, height, ParameterMap.V));
        return new(crossSection.Seed, cascade, crossSection.UStart, crossSection.UEnd);
    }

    /// <summary>
    /// A seashell: the torus's tube circle (radius r at distance R from the z axis) coiled about z by
    /// 2π turns v and lifted by h v (a full twist), then scaled about the origin by e^(g v) so each
    /// whorl shrinks (g &lt; 0) or grows: e^(g v) (Rz(2π k v) ((R + r cos 2πu), 0, −r sin 2πu) + (0, 0, h v)).
    /// </summary>
    public static SingleTwistSurface Seashell(double majorRadius, double minorRadius, double turns, double height, double growth)
    {
        Require.Finite(majorRadius, nameof(majorRadius));
        Require.Finite(minorRadius, nameof(minorRadius));
        Require.Finite(turns, nameof(turns));
        Require.Finite(height, nameof(height));
        Require.Finite(growth, nameof(growth));
        var cascade = TwistCascade.Empty
            .RotateAbout(Y, new(majorRadius, 0, 0), 2 * Math.PI, ParameterMap.U)
            .Then(new FullTwist(Z, default, 2 * Math.PI * turns, ParameterMap.V, height, ParameterMap.V))
            .Then(new ScalingTwist(default, growth, ParameterMap.V));
        return new(new(majorRadius + minorRadius, 0, 0), cascade);
    }
}
