using RayTracer.Factories;

namespace RayTracer.Scenes.Lighting;

/// <summary>Only an ambient occluder: creases and contacts darken where the hemisphere is blocked.</summary>
public sealed class AmbientOcclusionScene : RoomScene
{
    public override string Name => "light-ambient-occlusion";
    public override string Description => "Ambient occlusion only (sampled hemisphere visibility).";

    protected override void AddLights(World world)
    {
        world.AmbientLight = LightFactory.AmbientOcclusion(world.ViewPlane.NumSamples, 1.2, 0.05);
    }
}
