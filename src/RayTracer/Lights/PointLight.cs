using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Lights;

/// <summary>
/// Light from a point. Radiance at distance r is ls·c / r^<see cref="FalloffPower"/>: 0 is Suffern's
/// artistic default (no fall-off), 2 the physical inverse-square law.
/// </summary>
public sealed class PointLight : Light
{
    public PointLight(Point3D location, double radianceScale = 1.0, RGBColor? color = null)
    {
        Location = location;
        RadianceScale = radianceScale;
        Color = color ?? RGBColor.White;
    }

    public Point3D Location { get; set; }
    public double RadianceScale { get; set; }
    public RGBColor Color { get; set; }
    public double FalloffPower { get; set; }

    public override Vector3D GetDirection(ShadingRecord sr) => (Location - sr.HitPoint).Normalized();

    public override RGBColor L(ShadingRecord sr)
    {
        var radiance = RadianceScale * Color;
        return FalloffPower == 0 ? radiance : radiance / Math.Pow(Location.Distance(sr.HitPoint), FalloffPower);
    }

    public override double ShadowDistance(in Ray ray) => Location.Distance(ray.o);
}
