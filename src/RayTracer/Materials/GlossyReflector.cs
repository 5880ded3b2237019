using RayTracer.BRDFs;
using RayTracer.Colors;

namespace RayTracer.Materials;

/// <summary>Phong plus blurred reflection: one sampled ray from a Phong lobe around the mirror direction.</summary>
public sealed class GlossyReflector : Phong
{
    private readonly GlossyScattering _blur;

    public GlossyReflector(double ka = 0.0, double kd = 0.0, RGBColor? cd = null, double ks = 0.0, double exponent = 100,
        double kr = 0.75, RGBColor? cr = null)
        : base(ka, kd, cd, ks, exponent)
    {
        GlossyBrdf = new GlossySpecular(kr, exponent, cr ?? RGBColor.White);
        _blur = new GlossyScattering(GlossyBrdf);
    }

    public GlossySpecular GlossyBrdf { get; }

    protected override SpecularScattering Specular => _blur;
}
