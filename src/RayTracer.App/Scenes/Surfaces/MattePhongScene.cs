using RayTracer.Colors;
using RayTracer.Materials;

namespace RayTracer.Scenes.Surfaces;

/// <summary>Matte spheres against Phong spheres of growing exponent.</summary>
public sealed class MattePhongScene : MaterialsScene
{
    public override string Name => "material-matte-phong";
    public override string Description => "Matte and Phong materials (exponents 5 to 500).";

    protected override Material MaterialFor(int index) => index == 0
        ? new Matte(0.25, 0.75, new RGBColor(0.9, 0.5, 0.2))
        : new Phong(0.25, 0.6, new RGBColor(0.9, 0.5, 0.2), 0.3, 5 * Math.Pow(Math.Sqrt(10), index - 1) * (index == 4 ? 1.6 : 1));
}
