using RayTracer.Maths;

namespace RayTracer.Geometry.Generic;

/// <summary>Azimuth about the +y axis measured from +z towards +x, in [0, 2π) (Suffern's convention for part objects).</summary>
internal static class Azimuth
{
    public static double Of(double x, double z)
    {
        double phi = Math.Atan2(x, z);
        return phi < 0 ? phi + MathConstants.TwoPi : phi;
    }

    public static void CheckRange(double min, double max)
    {
        if (!(min >= 0 && max <= MathConstants.TwoPi + Tolerances.RelativeRounding && min < max))
        {
            throw new ArgumentException($"Azimuth range [{min}, {max}] must satisfy 0 ≤ min < max ≤ 2π.");
        }
    }
}
