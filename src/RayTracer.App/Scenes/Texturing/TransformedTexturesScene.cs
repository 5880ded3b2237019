using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Tracing;
using RayTracer.Transforms;

namespace RayTracer.Scenes.Texturing;

/// <summary>One solid texture placed three ways by affine transforms: as is, scaled, and rotated.</summary>
public sealed class TransformedTexturesScene : SceneDescription
{
    public override string Name => "texture-transformed";
    public override string Description => "A solid checker and wood texture scaled, rotated and translated by affine transforms.";

    protected override void Populate(World world)
    {
        world.BackgroundColor = new RGBColor(0.1, 0.1, 0.12);
        world.AmbientLight = new AmbientLight(0.5);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.6, 0.6, 0.6)) });
        var checker = TextureFactory.Checker3D(0.5, new RGBColor(0.9, 0.3, 0.1), new RGBColor(0.95, 0.95, 0.9));
        var wood = TextureFactory.Wood();
        Texture<RGBColor>[] textures =
        [
            checker,
            new TransformedTexture<RGBColor>(checker, AffineTransform.Scaling(0.4, 2.5, 0.4)),
            new TransformedTexture<RGBColor>(checker, AffineTransform.RotationZ(0.7).Then(AffineTransform.RotationX(0.5))),
            new TransformedTexture<RGBColor>(wood, AffineTransform.RotationX(Math.PI / 2).Then(AffineTransform.Translation(3.3, 1, 0))),
        ];
        for (var i = 0; i < textures.Length; i++)
            world.Add(new Sphere(new Point3D(-3.3 + 2.2 * i, 1, 0), 1) { Material = MaterialFactory.Matte(textures[i], 0.35, 0.75) });
        world.Add(LightFactory.Point(new Point3D(2, 8, 8), 1.1));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2.2, 8.5), new Point3D(0, 1, 0), 62, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
