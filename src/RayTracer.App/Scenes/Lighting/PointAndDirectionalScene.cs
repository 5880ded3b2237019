using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Lights;
using RayTracer.Maths;

namespace RayTracer.Scenes.Lighting;

/// <summary>Hard shadows from a coloured point light with inverse-square fall-off and a directional light.</summary>
public sealed class PointAndDirectionalScene : RoomScene
{
    public override string Name => "light-point-directional";
    public override string Description => "Point light (inverse-square) and directional light with hard shadows, plus ambient.";

    protected override void AddLights(World world)
    {
        world.AmbientLight = new AmbientLight(0.25);
        world.Add(new PointLight(new Point3D(-3, 5, 4), 40, new RGBColor(1, 0.9, 0.75)) { FalloffPower = 2 });
        world.Add(LightFactory.Directional(new Vector3D(2, 3, 1.5), 0.7, new RGBColor(0.7, 0.8, 1.0)));
    }
}
