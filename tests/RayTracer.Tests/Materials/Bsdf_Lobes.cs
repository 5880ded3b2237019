using RayTracer.Colors;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Materials;

public class Bsdf_Lobes
{
    private static ShadingRecord HitFrom(Vector3D towardsSurface) => new()
    {
        Normal = new Normal3D(0, 0, 1),
        Ray = new Ray(new Point3D(0, 0, 1), towardsSurface),
    };

    [Fact]
    public void A_diffuse_bounce_has_the_density_pdf_reports_and_carries_kd_cd()
    {
        var sr = HitFrom(new Vector3D(0.3, 0, -1).Normalized());
        var wo = -sr.Ray.d.Normalized();
        var bsdf = new Matte(0.1, 0.7, new RGBColor(1, 0.5, 0.25)).GetBsdf(sr);
        Span<BsdfSample> samples = stackalloc BsdfSample[SpecularScattering.MaxSamples];
        for (var i = 0; i < 50; i++)
        {
            Assert.Equal(1, bsdf.SampleBounce(wo, samples));
            var s = samples[0];
            Assert.Equal(s.Wi.z / Math.PI, bsdf.Pdf(wo, s.Wi), 12); // cosine-weighted density
            Assert.Equal(bsdf.F(wo, s.Wi), s.F);
            // f·cos/pdf of a cosine-sampled Lambertian lobe is its reflectance kd·cd.
            Assert.Equal(0.35, (s.F * s.Weight).g, 12);
        }
        Assert.Equal(0, bsdf.SampleSpecular(wo, samples));
    }

    [Fact]
    public void A_dielectric_at_normal_incidence_splits_by_the_fresnel_reflectance()
    {
        var sr = HitFrom(new Vector3D(0, 0, -1));
        var wo = -sr.Ray.d;
        var bsdf = new Dielectric(1.5, 1.0).GetBsdf(sr);
        Span<BsdfSample> samples = stackalloc BsdfSample[SpecularScattering.MaxSamples];
        Assert.True(bsdf.Transmits);
        Assert.Equal(2, bsdf.SampleSpecular(wo, samples));
        var r = Math.Pow(0.5 / 2.5, 2); // ((n − 1) / (n + 1))²
        Assert.Equal(r, (samples[0].F * samples[0].Weight).r, 12);
        Assert.Equal(1.0, samples[0].Wi.z, 12);
        // Radiance entering the denser medium is compressed by n².
        Assert.Equal((1 - r) / (1.5 * 1.5), (samples[1].F * samples[1].Weight).r, 12);
        Assert.Equal(-1.0, samples[1].Wi.z, 12);
        Assert.Equal(bsdf.SampleSpecular(wo, samples), bsdf.SampleBounce(wo, samples));
    }

    [Fact]
    public void Light_inside_glass_beyond_the_critical_angle_is_all_reflected()
    {
        // From inside (the ray travels along +z through the surface) at 60° > asin(1/1.5).
        var d = new Vector3D(Math.Sin(MathConstants.ToRadians(60)), 0, Math.Cos(MathConstants.ToRadians(60)));
        var sr = HitFrom(d);
        Span<BsdfSample> samples = stackalloc BsdfSample[SpecularScattering.MaxSamples];
        var count = new Transparent(kr: 0.1, kt: 0.9, ior: 1.5).GetBsdf(sr).SampleSpecular(-d, samples);
        Assert.Equal(1, count);
        Assert.Equal(RGBColor.White, samples[0].F * samples[0].Weight);
        Assert.Equal(-d.z, samples[0].Wi.z, 12);
    }

    [Fact]
    public void An_emitter_scatters_nothing_and_a_mirror_only_by_its_specular_lobe()
    {
        var sr = HitFrom(new Vector3D(0, 0, -1));
        Assert.True(new Emissive(2.0).GetBsdf(sr).IsEmpty);
        var mirror = new Reflective(0.2, 0.5, RGBColor.White, 0.1, 20, 0.75).GetBsdf(sr);
        Assert.True(mirror.MeetsLights && mirror.HasSpecular && !mirror.Transmits);
        Assert.Equal(0.0, mirror.Pdf(new Vector3D(0, 0, 1), new Vector3D(0, 0, 1)));
    }
}
