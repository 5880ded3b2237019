namespace RayTracer.Viewing;

/// <summary>
/// Projection surfaces of the camera catalogue in the rest frame (eye at the origin, looking along −e3,
/// e2 up), each a Twister cascade of turns and shifts applied to a seed point. Angles in radians.
/// </summary>
public static class GpcmSurfaces
{
    /// <inheritdoc cref="SphereLens"/>
    public static SphereLens Sphere(double maxAzimuth, double maxElevation) => new(maxAzimuth, maxElevation);

    /// <inheritdoc cref="CylinderLens"/>
    public static CylinderLens Cylinder(double maxAzimuth, double height) => new(maxAzimuth, height);

    /// <inheritdoc cref="ConeLens"/>
    public static ConeLens Cone(double maxAzimuth, double slant, double tilt) => new(maxAzimuth, slant, tilt);

    /// <inheritdoc cref="CapLens"/>
    public static CapLens Cap(double maxAngleFromAxis) => new(maxAngleFromAxis);
}
