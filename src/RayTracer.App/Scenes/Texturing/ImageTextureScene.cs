using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Geometry;
using RayTracer.Geometry.Generic;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Maths;
using RayTracer.Textures.Images;
using RayTracer.Textures.Mappings;
using RayTracer.Tracing;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Scenes.Texturing;

/// <summary>
/// One image on a sphere (spherical map), a cylinder (cylindrical map) and a square (rectangular map). The
/// image is drawn in code, so the scene needs no files; <see cref="SceneSettings.ImagePath"/> can point at
/// a PNG, JPEG, TGA, BMP or HDR file instead.
/// </summary>
public sealed class ImageTextureScene : SceneDescription
{
    public override string Name => "texture-image";
    public override string Description => "Image texture with spherical, cylindrical and rectangular mappings.";

    public override bool UsesImage => true;

    /// <summary>A labelled test card: colour bands by longitude, darker towards the poles, a grid every 1/8.</summary>
    public static PixelImage TestCard(int width = 256, int height = 128)
    {
        var image = new PixelImage(width, height, 3);
        for (var y = 0; y < height; y++)
        for (var x = 0; x < width; x++)
        {
            var u = (x + 0.5) / width;
            var v = (y + 0.5) / height;
            var hue = u * 6;
            var band = (int)hue % 6;
            double r = band is 0 or 5 ? 1 : band is 1 ? 2 - hue : band is 4 ? hue - 4 : 0;
            double g = band is 1 or 2 ? 1 : band == 0 ? hue : band == 3 ? 4 - hue : 0;
            double b = band is 3 or 4 ? 1 : band == 2 ? hue - 2 : band == 5 ? 6 - hue : 0;
            var shade = 0.35 + 0.65 * Math.Sin(Math.PI * v);
            var grid = (x % (width / 8) == 0 || y % (height / 4) == 0) ? 0.15 : 1.0;
            image[x, y, 0] = (byte)(255 * Math.Clamp(r * shade * grid, 0, 1));
            image[x, y, 1] = (byte)(255 * Math.Clamp(g * shade * grid, 0, 1));
            image[x, y, 2] = (byte)(255 * Math.Clamp(b * shade * grid, 0, 1));
        }
        return image;
    }

    protected override void Populate(World world)
    {
        var path = Settings.ImagePath;
        var image = path is null ? RadianceImage.FromPixels(TestCard(), 2.2) : ImageFile.ReadRadiance(path, 2.2);
        world.BackgroundColor = new RGBColor(0.12, 0.12, 0.14);
        world.AmbientLight = new AmbientLight(0.5);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 1, 0)) { Material = MaterialFactory.Matte(new RGBColor(0.6, 0.6, 0.6)) });

        var spherical = new ImageTexture(image) { Mapping = new SphericalMapping() };
        world.Add(WithMaterial(new Instance(new Sphere(Point3D.Origin, 1)).RotateY(0.6).Translate(-2.6, 1, 0), MaterialFactory.Matte(spherical, 0.3, 0.8)));

        var cylindrical = new ImageTexture(image) { Mapping = new CylindricalMapping() };
        world.Add(WithMaterial(new Instance(new OpenCylinder(-1, 1, 1)).Translate(0, 1, 0), MaterialFactory.Matte(cylindrical, 0.3, 0.8)));

        var rectangular = new ImageTexture(image) { Mapping = new RectangularMapping() };
        world.Add(WithMaterial(new Instance(new Rectangle(new Point3D(-1, 0, -1), new Vector3D(0, 0, 2), new Vector3D(2, 0, 0))).RotateX(Math.PI / 2).Translate(2.6, 1.1, 0),
            MaterialFactory.Matte(rectangular, 0.3, 0.8)));

        world.Add(LightFactory.Point(new Point3D(0, 6, 9), 1.2));
        world.Camera = CameraFactory.Pinhole(new Point3D(0, 2, 8), new Point3D(0, 1, 0), 60, world.ViewPlane);
        world.Integrator = new RayCastIntegrator(world);
    }
}
