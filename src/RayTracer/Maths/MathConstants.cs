namespace RayTracer.Maths;

/// <summary>Numeric constants shared by intersection and sampling code.</summary>
public static class MathConstants
{
    public const double Pi = Math.PI;
    public const double TwoPi = 2.0 * Math.PI;
    public const double InvPi = 1.0 / Math.PI;
    public const double InvTwoPi = 0.5 / Math.PI;

    /// <summary>Minimum ray parameter accepted as a hit; avoids self-intersection ("shadow acne").</summary>
    public const double Epsilon = 1e-7;

    /// <summary>Stands in for infinity where arithmetic on it must stay finite.</summary>
    public const double HugeValue = 1.0e10;

    public static double ToRadians(double degrees) => degrees * (Math.PI / 180.0);
}
