using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>Light from infinitely far away in a fixed direction (the sun).</summary>
public sealed class DirectionalLight : Light
{
    private Vector3D _direction = Vector3D.UnitY;

    public DirectionalLight(Vector3D towardsLight, double radianceScale = 1.0, RGBColor? color = null)
    {
        Direction = towardsLight;
        RadianceScale = radianceScale;
        Color = color ?? RGBColor.White;
    }

    /// <summary>Unit direction pointing towards the light.</summary>
    public Vector3D Direction
    {
        get => _direction;
        set => _direction = value.Normalized();
    }

    public double RadianceScale { get; set; }
    public RGBColor Color { get; set; }

    public override Vector3D GetDirection(ShadingRecord sr) => _direction;

    public override RGBColor L(ShadingRecord sr) => RadianceScale * Color;

}
