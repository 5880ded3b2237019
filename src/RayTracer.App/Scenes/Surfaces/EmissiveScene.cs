using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Textures.Noise;
using RayTracer.Textures.Solid;

namespace RayTracer.Scenes.Surfaces;

/// <summary>Glowing spheres: plain emissive ones and spatially varying ones whose emission is a texture.</summary>
public sealed class EmissiveScene : MaterialsScene
{
    public override string Name => "material-emissive";
    public override string Description => "Emissive materials, plain and textured, between matte spheres.";

    protected override Material MaterialFor(int index) => index switch
    {
        0 => new Emissive(1.5, new RGBColor(1.0, 0.6, 0.2)),
        1 => new Emissive(1.2, TextureFactory.SphereChecker(12, 6, new RGBColor(0.2, 0.9, 1.0), new RGBColor(0.05, 0.05, 0.1), new Point3D(-2, 0.85, 0))),
        2 => new Matte(0.25, 0.75, new RGBColor(0.8, 0.8, 0.8)),
        3 => new Emissive(1.0, new RampTexture(new CubicNoise(5), [new RGBColor(0.1, 0, 0), new RGBColor(1, 0.3, 0), new RGBColor(1, 0.9, 0.3)], 5, 4)),
        _ => new Emissive(0.9, new RGBColor(0.6, 0.4, 1.0)),
    };
}
