namespace RayTracer.Maths;

/// <summary>
/// The small numbers the renderer compares or pads with, each named for what it guards against. Doubles
/// carry about 16 significant digits (machine epsilon 2.2e-16); each tolerance sits many orders of magnitude
/// above the rounding it absorbs and many below any size a scene is built from.
/// </summary>
public static class Tolerances
{
    /// <summary>
    /// Absolute padding (scene units) of bounding boxes: flat shapes (disks, rectangles, annuli) have boxes of
    /// zero thickness, and a slab test against a face lying exactly on a box side may miss it by rounding.
    /// 1e-9 gives every box volume without measurably loosening it for scenes from millimetres to kilometres.
    /// </summary>
    public const double BoundsPadding = 1e-9;

    /// <summary>
    /// Relative shortening of a shadow ray that ends on a light's surface, so the light does not shadow itself:
    /// the hit on the sampled point is computed with a relative error near 1e-15, well inside 1e-9, while an
    /// occluder would need to lie within a billionth of the distance of the light to be missed.
    /// </summary>
    public const double ShadowRayShortening = 1e-9;

    /// <summary>
    /// Relative rounding of a value computed in a few double operations (a few ulps, ~1e-15), with a wide margin:
    /// below it two quantities (an angle and π, a dot product and −1, a ratio and 1) are taken as equal.
    /// </summary>
    public const double RelativeRounding = 1e-12;
}
