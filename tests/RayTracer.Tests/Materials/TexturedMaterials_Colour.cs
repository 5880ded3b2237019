using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Materials;

public class TexturedMaterials_Colour
{
    private static readonly RGBColor Light = new(0.9, 0.2, 0.1), Dark = new(0.1, 0.3, 0.7);

    // Unit checker cells: (0.5, 0.5, 0.5) and (1.5, 0.5, 0.5) lie in cells of opposite colour.
    private static readonly Vector3D Up = new(0, 0, 1);

    private static readonly Point3D[] Points = [new(0.5, 0.5, 0.5), new(1.5, 0.5, 0.5)];

    private static ShadingRecord AmbientOnlyHit(Point3D local)
    {
        return new ShadingRecord
        {
            HitPoint = local,
            LocalHitPoint = local,
            Normal = new Normal3D(0, 0, 1),
            Ray = new Ray(new Point3D(local.x, local.y, 5), new Vector3D(0, 0, -1)),
        };
    }

    [Fact]
    public void Matte_with_a_texture_reflects_the_texture_colour_at_each_hit()
    {
        var checker = TextureFactory.Checker3D(1, Light, Dark);
        var matte = new Matte(0.4, 0.6, checker);
        foreach (var p in Points)
        {
            var sr = AmbientOnlyHit(p);
            Assert.Equal(0.4 * checker.GetValue(sr), matte.AmbientReflectance(sr));
            Assert.Equal(0.6 * MathConstants.InvPi * checker.GetValue(sr), matte.GetBsdf(sr).F(Up, Up));
        }
        Assert.NotEqual(checker.GetValue(AmbientOnlyHit(Points[0])), checker.GetValue(AmbientOnlyHit(Points[1])));
    }

    [Fact]
    public void Phong_with_a_texture_takes_its_diffuse_colour_from_the_texture()
    {
        var checker = TextureFactory.Checker3D(1, Light, Dark);
        var phong = new Phong(0.3, 0.6, checker, 0.2, 20);
        foreach (var p in Points)
        {
            var sr = AmbientOnlyHit(p);
            Assert.Equal(0.3 * checker.GetValue(sr), phong.AmbientReflectance(sr));
            Assert.Equal(0.6 * checker.GetValue(sr), phong.DiffuseBrdf.Rho(sr, default));
        }
    }

    [Fact]
    public void Plain_colour_materials_equal_the_same_colour_as_a_constant_texture()
    {
        var sr = AmbientOnlyHit(Points[0]);
        Assert.Equal(new Matte(0.4, 0.6, TextureFactory.Constant(Light)).AmbientReflectance(sr), new Matte(0.4, 0.6, Light).AmbientReflectance(sr));
        Assert.Equal(new Matte(0.4, 0.6, TextureFactory.Constant(Light)).GetBsdf(sr).F(Up, Up), new Matte(0.4, 0.6, Light).GetBsdf(sr).F(Up, Up));
        Assert.Equal(new Emissive(1.5, TextureFactory.Constant(Light)).GetLe(sr), new Emissive(1.5, Light).GetLe(sr));
    }
}
