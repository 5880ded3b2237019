using RayTracer.Colors;
using RayTracer.Textures;

namespace RayTracer.Materials;

/// <summary>Phong material whose diffuse colour comes from a texture.</summary>
public sealed class SVPhong(double ka, double kd, Texture<RGBColor> color, double ks, double exponent, RGBColor? cs = null)
    : Phong(ka, kd, color, ks, exponent, cs)
{
    public Texture<RGBColor> Color { get; } = color;
}
