namespace RayTracer.Viewing;

/// <summary>Which way a generalized pinhole camera's primary rays run along the line through the eye and the surface point.</summary>
public enum GpcmRayDirection
{
    /// <summary>From the eye through the surface point.</summary>
    Outward,

    /// <summary>From the surface point back through the eye: with surface origins, the scene behind the camera seen through the surface.</summary>
    Inward,
}
