namespace RayTracer.Viewing;

/// <summary>Where a generalized pinhole camera's primary rays start (thesis §6.5.3).</summary>
public enum GpcmRayOrigin
{
    /// <summary>At the eye: the classic pinhole.</summary>
    Eye,

    /// <summary>On the projection surface: the surface cuts the scene, hiding what lies between it and the eye.</summary>
    Surface,
}
