using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Textures;
using RayTracer.Textures.Conversions;
using RayTracer.Textures.Images;
using RayTracer.Textures.Mappings;
using RayTracer.Textures.Noise;
using RayTracer.Textures.Patterns;
using RayTracer.Textures.Solid;
using RayTracer.Tracing;
using RayTracer.Transforms;
using RayTracer.Viewing.Imaging;

namespace RayTracer.Tests.Textures;

public class Textures_Patterns
{
    private static ShadingRecord At(Point3D local, double u = 0, double v = 0) =>
        new() { LocalHitPoint = local, TextureCoordinates = new TextureCoordinates(u, v) };

    [Fact]
    public void Checker_2d_alternates_between_neighbouring_checks()
    {
        var checker = new Checker2D(4, 2);
        Assert.True(checker.Evaluate(0.1, 0.1));
        Assert.False(checker.Evaluate(0.3, 0.1));
        Assert.False(checker.Evaluate(0.1, 0.6));
        Assert.True(checker.Evaluate(0.3, 0.6));
        Assert.True(checker.GetValue(At(Point3D.Origin, 0.3, 0.6)));
    }

    [Fact]
    public void Checker_3d_and_plane_checker_flip_across_cell_boundaries()
    {
        var solid = new Checker3D(2.0);
        Assert.NotEqual(solid.Evaluate(new Point3D(0.5, 0.5, 0.5)), solid.Evaluate(new Point3D(2.5, 0.5, 0.5)));
        Assert.Equal(solid.Evaluate(new Point3D(0.5, 0.5, 0.5)), solid.Evaluate(new Point3D(2.5, 2.5, 0.5)));
        var plane = new PlaneChecker(1.0);
        Assert.Equal(plane.Evaluate(new Point3D(0.5, 0, 0.5)), plane.Evaluate(new Point3D(0.5, 99, 0.5)));
        Assert.NotEqual(plane.Evaluate(new Point3D(0.5, 0, 0.5)), plane.Evaluate(new Point3D(-0.5, 0, 0.5)));
    }

    [Fact]
    public void Sphere_checker_does_not_depend_on_the_radius()
    {
        var checker = new SphereChecker(8, 4) { Center = new Point3D(1, 1, 1) };
        var direction = new Vector3D(0.3, 0.5, -0.8).Normalized();
        Assert.Equal(checker.Evaluate(checker.Center + direction), checker.Evaluate(checker.Center + 5 * direction));
        // Crossing the equator changes the check.
        Assert.NotEqual(checker.Evaluate(new Point3D(1, 1.1, 2)), checker.Evaluate(new Point3D(1, 0.9, 2)));
    }

    [Fact]
    public void Spherical_mapping_sends_poles_and_meridians_to_the_expected_uv()
    {
        var map = new SphericalMapping();
        Assert.Equal(1.0, map.Map(new Point3D(0, 1, 0)).v, 12);
        Assert.Equal(0.0, map.Map(new Point3D(0, -1, 0)).v, 12);
        Assert.Equal(0.5, map.Map(new Point3D(0, 0, 1)).v, 12);
        Assert.Equal(0.0, map.Map(new Point3D(0, 0, 1)).u, 12);
        Assert.Equal(0.25, map.Map(new Point3D(1, 0, 0)).u, 12);
        Assert.Equal(0.75, map.Map(new Point3D(-1, 0, 0)).u, 12);
        var cylinder = new CylindricalMapping().Map(new Point3D(0, 0.5, -1));
        Assert.Equal(0.5, cylinder.u, 12);
        Assert.Equal(0.75, cylinder.v, 12);
        var square = new RectangularMapping().Map(new Point3D(-1, 0, 1));
        Assert.Equal(1.0, square.u, 12);
        Assert.Equal(0.0, square.v, 12);
    }

    [Fact]
    public void Image_texture_reads_the_pixel_under_uv_with_v_up()
    {
        var image = new PixelImage(2, 2, 3);
        image[0, 0, 0] = 255; // top left red
        image[1, 1, 2] = 255; // bottom right blue
        var texture = new ImageTexture(image);
        Assert.Equal(new RGBColor(1, 0, 0), texture.Evaluate(0.25, 0.75));
        Assert.Equal(new RGBColor(0, 0, 1), texture.Evaluate(0.75, 0.25));
        Assert.Equal(new RGBColor(0, 0, 1), texture.Evaluate(1.0, 0.0)); // edges clamp
        texture.Mapping = new RectangularMapping();
        Assert.Equal(new RGBColor(1, 0, 0), texture.GetValue(At(new Point3D(0.9, 0, -0.9))));
    }

    [Fact]
    public void Conversions_between_texture_kinds()
    {
        var noise = new LinearNoise(3);
        var scalar = new NoiseTexture(noise, NoiseKind.Fbm, scale: 2);
        var p = new Point3D(0.3, 1.7, -2.2);
        Assert.Equal(noise.Fbm(0.6, 3.4, -4.4), scalar.Evaluate(p), 12);
        var binary = new ThresholdTexture(scalar, 0.5);
        Assert.Equal(scalar.Evaluate(p) > 0.5, binary.GetValue(At(p)));
        var colored = new BinaryColorTexture(binary, new RGBColor(1, 0, 0), new RGBColor(0, 1, 0));
        Assert.Equal(binary.GetValue(At(p)) ? new RGBColor(1, 0, 0) : new RGBColor(0, 1, 0), colored.GetValue(At(p)));
        var blend = new ScalarColorTexture(new ConstantTexture<double>(0.25), RGBColor.Black, new RGBColor(4, 4, 4));
        Assert.Equal(new RGBColor(1, 1, 1), blend.GetValue(At(p)));
        var vectors = new NoiseVectorTexture(noise);
        var v = vectors.Evaluate(p);
        Assert.InRange(v.x, -1, 1);
        Assert.NotEqual(v.x, v.y);
        var shown = new VectorColorTexture(new ConstantTexture<Vector3D>(new Vector3D(-1, 0, 1))).GetValue(At(p));
        Assert.Equal(new RGBColor(0, 0.5, 1), shown);
    }

    [Fact]
    public void Transformed_texture_evaluates_the_inner_one_at_the_inverse_point()
    {
        var inner = new Checker3D(1.0);
        var moved = new TransformedTexture<bool>(inner, AffineTransform.Translation(0.5, 0, 0));
        var sr = At(new Point3D(0.75, 0.2, 0.2));
        Assert.Equal(inner.Evaluate(new Point3D(0.25, 0.2, 0.2)), moved.GetValue(sr));
        Assert.Equal(new Point3D(0.75, 0.2, 0.2), sr.LocalHitPoint); // restored afterwards
        var scaled = new TransformedTexture<bool>(inner, AffineTransform.Scaling(3));
        Assert.Equal(inner.Evaluate(new Point3D(0.5, 0.1, 0.1)), scaled.GetValue(At(new Point3D(1.5, 0.3, 0.3))));
    }

    [Fact]
    public void Marble_and_wood_stay_within_their_colours()
    {
        var noise = new CubicNoise(4);
        var marble = new RampTexture(noise, [new RGBColor(0.2, 0.2, 0.2), new RGBColor(1, 1, 1)]);
        Assert.Equal(new RGBColor(0.6, 0.6, 0.6), marble.Lookup(0.5));
        var wood = new WoodTexture(noise, new RGBColor(0.8, 0.6, 0.3), new RGBColor(0.4, 0.2, 0.1));
        var random = new Random(5);
        for (var i = 0; i < 200; i++)
        {
            var p = new Point3D(random.NextDouble() * 4 - 2, random.NextDouble() * 4 - 2, random.NextDouble() * 4 - 2);
            var m = marble.Evaluate(p);
            Assert.InRange(m.r, 0.2 - 1e-12, 1 + 1e-12);
            var w = wood.Evaluate(p);
            Assert.InRange(w.r, 0.4 * 0.85 - 1e-12, 0.8 + 1e-12);
            Assert.InRange(wood.RingPhase(p), 0, 1);
        }
        Assert.Throws<ArgumentException>(() => new RampTexture(noise, [RGBColor.White]));
    }
}
