using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Materials;

public class Fresnel_Optics
{
    private static readonly Normal3D Up = new(0, 0, 1);

    private static Vector3D FromAngle(double degrees) =>
        new(Math.Sin(MathConstants.ToRadians(degrees)), 0, Math.Cos(MathConstants.ToRadians(degrees)));

    [Fact]
    public void Normal_incidence_reflectance_is_the_classic_formula()
    {
        // R0 = ((n1 - n2) / (n1 + n2))², 0.04 for glass in air.
        Assert.Equal(0.04, FresnelReflector.Reflectance(FromAngle(0), Up, 1.5, 1.0), 12);
        Assert.Equal(Math.Pow(0.33 / 2.33, 2), FresnelReflector.Reflectance(FromAngle(0), Up, 1.33, 1.0), 12);
    }

    [Fact]
    public void Reflectance_reaches_one_at_grazing_and_beyond_the_critical_angle()
    {
        Assert.Equal(1.0, FresnelReflector.Reflectance(FromAngle(89.9999), Up, 1.5, 1.0), 3);
        // From inside glass (wo below the surface), the critical angle is asin(1/1.5) ≈ 41.8°.
        var inside = -FromAngle(45);
        Assert.Equal(1.0, FresnelReflector.Reflectance(inside, Up, 1.5, 1.0));
        Assert.True(FresnelReflector.Reflectance(-FromAngle(40), Up, 1.5, 1.0) < 1.0);
        Assert.False(BTDF.Refract(inside, Up, 1.5, out _, out _));
    }

    [Theory]
    [InlineData(10.0)]
    [InlineData(35.0)]
    [InlineData(70.0)]
    public void Refraction_obeys_snells_law(double degrees)
    {
        var wo = FromAngle(degrees);
        Assert.True(BTDF.Refract(wo, Up, 1.5, out var wt, out var cosT));
        Assert.Equal(1.0, wt.Length, 12);
        Assert.True(wt.z < 0);
        var sinT = Math.Sqrt(wt.x * wt.x + wt.y * wt.y);
        Assert.Equal(Math.Sin(MathConstants.ToRadians(degrees)) / 1.5, sinT, 12);
        Assert.Equal(-wt.z, cosT, 12);
        Assert.True(wt.x < 0); // transmitted ray continues away from the side wo came from
    }

    [Fact]
    public void Beer_law_attenuates_exponentially_with_distance()
    {
        var filter = new RGBColor(0.5, 0.8, 1.0);
        var twoUnits = Dielectric.Attenuation(filter, 2);
        Assert.Equal(0.25, twoUnits.r, 12);
        Assert.Equal(0.64, twoUnits.g, 12);
        Assert.Equal(1.0, twoUnits.b, 12);
        Assert.Equal(RGBColor.White, Dielectric.Attenuation(filter, MathConstants.HugeValue));
    }

    [Fact]
    public void Brdfs_have_their_defining_values()
    {
        var sr = new ShadingRecord() { Normal = Up };
        var lambertian = new Lambertian(0.6, new RGBColor(1, 0.5, 0));
        Assert.Equal(0.6 / Math.PI, lambertian.F(sr, FromAngle(10), FromAngle(50)).r, 12);
        Assert.Equal(0.3, lambertian.Rho(sr, FromAngle(0)).g, 12);
        // Phong lobe peaks in the mirror direction with value ks.
        var glossy = new GlossySpecular(0.4, 30);
        var wi = FromAngle(30);
        var mirror = new Vector3D(-wi.x, -wi.y, wi.z);
        Assert.Equal(0.4, glossy.F(sr, mirror, wi).r, 12);
        Assert.Equal(0.4 * Math.Pow(Math.Cos(MathConstants.ToRadians(10)), 30), glossy.F(sr, FromAngle(-40), wi).r, 9);
        // Perfect specular returns the mirror direction.
        var specular = new PerfectSpecular(0.7);
        var f = specular.SampleF(sr, FromAngle(25), out var reflected, out _);
        Assert.Equal(FromAngle(-25).x, reflected.x, 12);
        Assert.Equal(0.7, f.r * Math.Abs(Up.Dot(reflected)), 12);
    }
}
