namespace RayTracer.Maths;

/// <summary>Numeric constants shared by intersection and sampling code.</summary>
public static class MathConstants
{
    public const double Pi = Math.PI;
    public const double TwoPi = 2.0 * Math.PI;
    public const double InvPi = 1.0 / Math.PI;
    public const double InvTwoPi = 0.5 / Math.PI;

    /// <summary>
    /// Minimum ray parameter accepted as a hit, relative to the scene's size: a world sets its rays' to
    /// this times its extent (<see cref="Scenes.World.RayEpsilon"/>); rays built without a world use it as is.
    /// </summary>
    public const double Epsilon = 1e-7;

    /// <summary>
    /// The distance of "no hit": infinite, so that no scene is too large to be seen (a finite cap hid every
    /// object of a scene larger than it). Only compared against, never used in arithmetic.
    /// </summary>
    public const double HugeValue = double.PositiveInfinity;

    public static double ToRadians(double degrees) => degrees * (Math.PI / 180.0);
}
