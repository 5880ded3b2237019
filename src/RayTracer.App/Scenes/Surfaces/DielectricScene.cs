using RayTracer.Colors;
using RayTracer.Materials;

namespace RayTracer.Scenes.Surfaces;

/// <summary>Fresnel dielectrics: clear glass, water, and Beer's-law tinted glasses.</summary>
public sealed class DielectricScene : MaterialsScene
{
    public override string Name => "material-dielectric";
    public override string Description => "Dielectrics with Fresnel reflection/refraction and Beer's-law colour filtering.";
    public override int DefaultMaxDepth => 8;

    protected override Material MaterialFor(int index) => index switch
    {
        0 => new Dielectric(1.5, 1.0),
        1 => new Dielectric(1.33, 1.0, new RGBColor(0.8, 0.95, 1.0)),
        2 => new Dielectric(1.5, 1.0, new RGBColor(0.65, 0.45, 0.0)),
        3 => new Dielectric(1.5, 1.0, new RGBColor(0.3, 0.75, 0.3)),
        _ => new Dielectric(2.4, 1.0, new RGBColor(0.9, 0.9, 1.0)),
    };
}
