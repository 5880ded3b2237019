using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Maths;

namespace RayTracer.Scenes.Instancing;

/// <summary>
/// Figure 7-3a, reflective blocks: three large tubes in three materials (a mirror, shiny plastic
/// and plain plastic), one upright, one lying and one leaning, between two mirror-finished blocks,
/// so most tests come from reflected rays.
/// </summary>
public sealed class InstancingBlocksScene : InstancingScene
{
    public override string Name => "instancing-blocks";
    public override string Description => "Figure 7-3a: three large tubes of three materials between reflective blocks.";
    public override int DefaultMaxDepth => 4;

    protected override bool Joints => false;

    public override IReadOnlyList<CylinderSpec> Cylinders() =>
    [
        new(new Point3D(-1.6, 0, -0.4), new Vector3D(0, 2.6, 0), 0.8, MaterialFactory.Mirror(new RGBColor(0.9, 0.92, 1.0), 0.85)),
        new(new Point3D(0.2, 0.7, 1.2), new Vector3D(2.6, 0, -1.0), 0.7, MaterialFactory.Shiny(new RGBColor(0.80, 0.25, 0.20))),
        new(new Point3D(2.0, 0, -1.8), new Vector3D(-0.9, 2.2, 0.4), 0.6, TubeMaterial(new RGBColor(0.20, 0.45, 0.75))),
    ];

    protected override void Stage(World world)
    {
        AddFloor(world, 0, new RGBColor(0.72, 0.70, 0.66));
        var block = MaterialFactory.Shiny(new RGBColor(0.55, 0.55, 0.5));
        world.Add(new Box(new Point3D(-4.2, 0, -3.5), new Point3D(-3.2, 1.6, 2.0)) { Material = block });
        world.Add(new Box(new Point3D(-2.5, 0, -4.4), new Point3D(3.8, 2.4, -3.6)) { Material = MaterialFactory.Mirror(new RGBColor(0.85, 0.9, 0.85), 0.7) });
        AddLights(world, new Point3D(-2, 7, 6));
        SetCamera(world, new Point3D(1.5, 3.2, 8.5), new Point3D(0, 1.0, -0.8), 55, reflections: true);
    }
}
