using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>Constant light from everywhere, used only in the ambient term.</summary>
public sealed class AmbientLight : Light
{
    public AmbientLight(double radianceScale = 1.0, RGBColor? color = null)
    {
        RadianceScale = radianceScale;
        Color = color ?? RGBColor.White;
        CastsShadows = false;
    }

    public double RadianceScale { get; set; }
    public RGBColor Color { get; set; }

    public override Vector3D GetDirection(ShadingRecord sr) => Vector3D.Zero;

    public override RGBColor L(ShadingRecord sr) => RadianceScale * Color;
}
