using RayTracer.Materials;

namespace RayTracer.Scenes.Surfaces;

/// <summary>Simple transparent spheres with indices of refraction 1.0 (invisible) to 2.0.</summary>
public sealed class TransparentScene : MaterialsScene
{
    public override string Name => "material-transparent";
    public override string Description => "Transparent material (fixed kr, kt) with IOR 1.0 to 2.0.";
    public override int DefaultMaxDepth => 8;

    protected override Material MaterialFor(int index) => new Transparent(ior: 1.0 + 0.25 * index);
}
