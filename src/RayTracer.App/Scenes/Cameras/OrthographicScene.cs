using RayTracer.Factories;
using RayTracer.Integrators;
using RayTracer.Scenes.Showcase;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Cameras;

/// <summary>The default scene in parallel projection: sizes do not shrink with distance.</summary>
public sealed class OrthographicScene : ShowcaseScene
{
    public override string Name => "camera-orthographic";
    public override string Description => "Default scene through an orthographic camera.";

    protected override void Populate(World world)
    {
        AddContent(world);
        world.Camera = CameraFactory.Orthographic(ViewEye, ViewTarget, 8.5, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }
}
