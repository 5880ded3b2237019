using RayTracer.Materials;

namespace RayTracer.Geometry;

/// <summary>
/// Surface properties shared by many primitives: material and shadow casting.
/// A mesh is one nature shared by all its triangles, so a million triangles do not carry a
/// million copies of the same settings.
/// </summary>
public class ObjectNature
{
    public Material? Material { get; set; }

    public bool CastsShadows { get; set; } = true;
}
