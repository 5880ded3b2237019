using RayTracer.Factories;
using RayTracer.Integrators;
using RayTracer.Scenes.Showcase;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Cameras;

/// <summary>Side-by-side stereo pair for parallel free viewing; the image is twice as wide plus a gap.</summary>
public sealed class StereoScene : ShowcaseScene
{
    public override string Name => "camera-stereo";
    public override string Description => "Default scene as a parallel-viewing stereo pair.";
    public override int DefaultWidth => 300;
    public override int DefaultHeight => 225;

    protected override void Populate(World world)
    {
        AddContent(world);
        world.Camera = CameraFactory.Stereo(ViewEye, ViewTarget, 55, 4, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }
}
