using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Lights;
using RayTracer.Maths;

namespace RayTracer.Scenes.Lighting;

/// <summary>A tilted warm disk light to one side.</summary>
public sealed class DiskLightScene : RoomScene
{
    public override string Name => "light-area-disk";
    public override string Description => "Disk area light (soft shadows).";

    protected override void AddLights(World world)
    {
        world.AmbientLight = new AmbientLight(0.05);
        var center = new Point3D(-3, 4, 2.5);
        var normal = new Normal3D(Point3D.Origin + new Vector3D(0, 1, 0) - center).Normalized();
        LightFactory.AddDiskLight(world, center, normal, 1.0, 9.0, new RGBColor(1, 0.85, 0.65));
    }
}
