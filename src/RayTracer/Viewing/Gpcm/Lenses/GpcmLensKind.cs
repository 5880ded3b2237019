using Twister;

namespace RayTracer.Viewing;

/// <summary>Which generated lens kernel serves a camera's rays, if any: fixed by its surface and mapping.</summary>
internal enum GpcmLensKind
{
    None,
    Rectangle,
    Sphere,
    Cylinder,
    Cone,
    Cap,
}

internal static class GpcmLensKinds
{
    /// <summary>The catalogue's rectangular lenses under the rectangular mapping, the cap under the polar one.</summary>
    public static GpcmLensKind Of(IParametricSurface surface, GpcmMapping mapping) => (surface, mapping) switch
    {
        (RectangularProjectionSurface, GpcmMapping.Rectangular) => GpcmLensKind.Rectangle,
        (SphereLens, GpcmMapping.Rectangular) => GpcmLensKind.Sphere,
        (CylinderLens, GpcmMapping.Rectangular) => GpcmLensKind.Cylinder,
        (ConeLens, GpcmMapping.Rectangular) => GpcmLensKind.Cone,
        (CapLens, GpcmMapping.Polar) => GpcmLensKind.Cap,
        _ => GpcmLensKind.None,
    };
}
