using RayTracer.Colors;
using RayTracer.Textures;

namespace RayTracer.Materials;

/// <summary>Emissive material whose emitted colour is a texture (a glowing image or pattern).</summary>
public sealed class SVEmissive(double radianceScale, Texture<RGBColor> color) : Emissive(radianceScale, color);
