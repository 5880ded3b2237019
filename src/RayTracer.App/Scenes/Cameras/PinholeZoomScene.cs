using RayTracer.Factories;
using RayTracer.Integrators;
using RayTracer.Maths;
using RayTracer.Scenes.Showcase;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Cameras;

/// <summary>The pinhole camera from a low, distant eye with zoom: perspective flattens as the view narrows.</summary>
public sealed class PinholeZoomScene : ShowcaseScene
{
    public override string Name => "camera-pinhole-zoom";
    public override string Description => "Default scene through a zoomed (x2.5) pinhole camera from far away.";

    protected override void Populate(World world)
    {
        AddContent(world);
        var camera = CameraFactory.Pinhole(new Point3D(4, 2, 20), ViewTarget, 55, world.ViewPlane);
        camera.Zoom = 2.5;
        world.Camera = camera;
        world.Integrator = new WhittedIntegrator(world);
    }
}
