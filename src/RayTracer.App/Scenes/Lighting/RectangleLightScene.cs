using RayTracer.Factories;
using RayTracer.Lights;
using RayTracer.Maths;

namespace RayTracer.Scenes.Lighting;

/// <summary>A rectangular ceiling panel: soft shadows with penumbrae.</summary>
public sealed class RectangleLightScene : RoomScene
{
    public override string Name => "light-area-rectangle";
    public override string Description => "Rectangular area light (soft shadows).";

    protected override void AddLights(World world)
    {
        world.AmbientLight = new AmbientLight(0.05);
        // a × b points down, so the panel emits towards the floor.
        LightFactory.AddRectangleLight(world, new Point3D(-1.5, 4.5, -1), new Vector3D(3, 0, 0), new Vector3D(0, 0, 2), 6.0);
    }
}
