using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Textures;

namespace RayTracer.Factories;

/// <summary>Ready-made materials with sensible coefficients.</summary>
public static class MaterialFactory
{
    public static Matte Matte(RGBColor color, double ka = 0.25, double kd = 0.75) => new(ka, kd, color);

    public static Matte Matte(Texture<RGBColor> texture, double ka = 0.25, double kd = 0.75) => new(ka, kd, texture);

    public static Phong Plastic(RGBColor color, double exponent = 50) => new(0.25, 0.6, color, 0.25, exponent);

    public static Phong Plastic(Texture<RGBColor> texture, double exponent = 50) => new(0.25, 0.6, texture, 0.25, exponent);

    public static Reflective Mirror(RGBColor tint, double kr = 0.9) => new(0.05, 0.05, tint, 0.0, 100, kr, tint);

    public static Reflective Shiny(RGBColor color) => new(0.25, 0.5, color, 0.15, 100, 0.35, RGBColor.White);

    public static GlossyReflector Glossy(RGBColor tint, double exponent = 100, double kr = 0.8) =>
        new(0.05, 0.1, tint, 0.0, exponent, kr, tint);

    public static Dielectric Glass(RGBColor? filterInside = null, double ior = 1.5) => new(ior, 1.0, filterInside);

    public static Emissive Light(double radiance, RGBColor? color = null) => new(radiance, color ?? RGBColor.White);
}
