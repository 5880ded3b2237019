using RayTracer.Colors;
using RayTracer.Textures;

namespace RayTracer.Materials;

/// <summary>Matte material whose colour comes from a texture (spatially varying).</summary>
public sealed class SVMatte(double ka, double kd, Texture<RGBColor> color) : Matte(ka, kd, color)
{
    public Texture<RGBColor> Color { get; } = color;
}
