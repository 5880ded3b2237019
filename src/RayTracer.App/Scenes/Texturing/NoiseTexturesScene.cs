using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Textures.Solid;
using RayTracer.Tracing;

namespace RayTracer.Scenes.Texturing;

/// <summary>Lattice noise four ways: linear value noise, cubic fBm, turbulence and wrapped fBm.</summary>
public sealed class NoiseTexturesScene : SceneDescription
{
    public override string Name => "texture-noise";
    public override string Description => "Value noise (linear), fBm (cubic), turbulence and wrapped fBm solid textures.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.1, 0.1, 0.12);
        world.AmbientLight = new AmbientLight(0.5);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.55, 0.55, 0.55)) });
        var textures = new[]
        {
            TextureFactory.Noise(NoiseKind.Value, new RGBColor(0.1, 0.1, 0.4), new RGBColor(0.9, 0.9, 1.0), scale: 4, octaves: 1, cubic: false),
            TextureFactory.Noise(NoiseKind.Fbm, new RGBColor(0.2, 0.1, 0.0), new RGBColor(1.0, 0.8, 0.4), scale: 3),
            TextureFactory.Noise(NoiseKind.Turbulence, new RGBColor(0.0, 0.15, 0.05), new RGBColor(0.6, 1.0, 0.6), scale: 3),
            TextureFactory.Noise(NoiseKind.WrappedFbm, new RGBColor(0.4, 0.05, 0.05), new RGBColor(1.0, 0.9, 0.9), scale: 1.5),
        };
        for (var i = 0; i < textures.Length; i++)
            world.Add(new Sphere(new Point3D(-3.3 + 2.2 * i, 1, 0), 1) { Material = MaterialFactory.Matte(textures[i], 0.35, 0.75) });
        world.Add(LightFactory.Point(new Point3D(2, 8, 8), 1.1));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.2, 8.5), new Point3D(0, 1, 0), 62, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
