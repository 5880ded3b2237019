using RayTracer.BRDFs;
using RayTracer.Colors;

namespace RayTracer.Materials;

/// <summary>Phong plus a perfect mirror lobe.</summary>
public class Reflective : Phong
{
    private readonly MirrorScattering _mirror;

    public Reflective(double ka = 0.25, double kd = 0.5, RGBColor? cd = null, double ks = 0.15, double exponent = 100,
        double kr = 0.75, RGBColor? cr = null)
        : base(ka, kd, cd, ks, exponent)
    {
        ReflectiveBrdf = new PerfectSpecular(kr, cr);
        _mirror = new MirrorScattering(ReflectiveBrdf);
    }

    public PerfectSpecular ReflectiveBrdf { get; }

    protected override SpecularScattering Specular => _mirror;
}
