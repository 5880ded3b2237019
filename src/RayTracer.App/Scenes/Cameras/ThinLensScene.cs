using RayTracer.Factories;
using RayTracer.Integrators;
using RayTracer.Maths;
using RayTracer.Scenes.Showcase;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Cameras;

/// <summary>Depth of field: focused on the mirror sphere, the others blur with distance from the focal plane.</summary>
public sealed class ThinLensScene : ShowcaseScene
{
    public override string Name => "camera-thin-lens";
    public override string Description => "Default scene through a thin-lens camera focused on the middle sphere.";
    public override int DefaultSamples => 36;

    protected override void Populate(World world)
    {
        AddContent(world);
        var focus = ViewEye.Distance(new Point3D(0, 1, -0.8));
        world.Camera = CameraFactory.ThinLens(ViewEye, ViewTarget, 55, focus, 0.25, world.ViewPlane);
        world.Integrator = new WhittedIntegrator(world);
    }
}
