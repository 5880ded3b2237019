using RayTracer.Factories;
using RayTracer.Integrators;
using RayTracer.Maths;
using RayTracer.Scenes.Showcase;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Cameras;

/// <summary>A 180° fisheye from close to the spheres: straight floor lines bend into arcs.</summary>
public sealed class FisheyeScene : ShowcaseScene
{
    public override string Name => "camera-fisheye";
    public override string Description => "Default scene through a 180-degree fisheye camera.";
    public override int DefaultWidth => 300;

    protected override void Populate(World world)
    {
        AddContent(world);
        world.Camera = CameraFactory.Fisheye(new Point3D(0, 1.5, 4), ViewTarget, 180);
        world.Integrator = new WhittedIntegrator(world);
    }
}
