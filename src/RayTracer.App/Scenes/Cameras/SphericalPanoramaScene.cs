using RayTracer.Factories;
using RayTracer.Integrators;
using RayTracer.Maths;
using RayTracer.Scenes.Showcase;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Cameras;

/// <summary>Full 360°×180° panorama from between the spheres.</summary>
public sealed class SphericalPanoramaScene : ShowcaseScene
{
    public override string Name => "camera-spherical";
    public override string Description => "Default scene as a 360x180-degree spherical panorama.";
    public override int DefaultWidth => 480;
    public override int DefaultHeight => 240;

    protected override void Populate(World world)
    {
        AddContent(world);
        world.Camera = CameraFactory.Spherical(new Point3D(0, 1.2, 1.8), new Point3D(0, 1.2, -1));
        world.Integrator = new WhittedIntegrator(world);
    }
}
