using RayTracer.Colors;
using RayTracer.Materials;

namespace RayTracer.Scenes.Surfaces;

/// <summary>Mirror spheres of increasing reflectance; they reflect each other up to the maximum depth.</summary>
public sealed class ReflectiveScene : MaterialsScene
{
    public override string Name => "material-reflective";
    public override string Description => "Perfect-specular (mirror) materials with kr from 0.2 to 1.";

    protected override Material MaterialFor(int index) =>
        new Reflective(0.2, 0.4, new RGBColor(0.3, 0.5, 0.9), 0.2, 200, 0.2 + 0.2 * index, RGBColor.White);
}
