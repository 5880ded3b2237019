using RayTracer.Materials;

namespace RayTracer.Geometry;

/// <summary>
/// Surface properties shared by many primitives: material, texture space and shadow casting.
/// A mesh is one nature shared by all its triangles, so a million triangles do not carry a
/// million copies of the same settings.
/// </summary>
public class ObjectNature
{
    public Material? Material { get; set; }

    /// <summary>Whether textures are looked up at the 3D local hit point (solid textures) or at (u, v).</summary>
    public bool UsesSolidTexture { get; set; }

    public bool CastsShadows { get; set; } = true;
}
