using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Lights;
using RayTracer.Maths;

namespace RayTracer.Scenes.Lighting;

/// <summary>A glowing sphere hanging above the objects.</summary>
public sealed class SphereLightScene : RoomScene
{
    public override string Name => "light-area-sphere";
    public override string Description => "Spherical area light (soft shadows, visible emitter).";

    protected override void AddLights(World world)
    {
        world.AmbientLight = new AmbientLight(0.05);
        LightFactory.AddSphereLight(world, new Point3D(0.5, 3.6, 1.5), 0.5, 12.0, new RGBColor(0.9, 0.95, 1));
    }
}
