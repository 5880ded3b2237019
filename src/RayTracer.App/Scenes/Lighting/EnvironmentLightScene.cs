using RayTracer.Colors;
using RayTracer.Factories;

namespace RayTracer.Scenes.Lighting;

/// <summary>Uniform sky light: soft, shadowless-looking illumination with occlusion in corners.</summary>
public sealed class EnvironmentLightScene : RoomScene
{
    public override string Name => "light-environment";
    public override string Description => "Uniform environment (sky) light sampled over the hemisphere.";

    protected override void AddLights(World world)
    {
        LightFactory.AddEnvironment(world, 0.9, new RGBColor(0.85, 0.9, 1.0), world.ViewPlane.NumSamples);
    }
}
