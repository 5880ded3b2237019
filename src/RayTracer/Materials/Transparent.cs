using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;

namespace RayTracer.Materials;

/// <summary>Phong surface with fixed-fraction mirror reflection and refraction (simple glass).</summary>
public sealed class Transparent : Phong
{
    private readonly SplitScattering _split;

    public Transparent(double ka = 0.0, double kd = 0.0, RGBColor? cd = null, double ks = 0.2, double exponent = 2000,
        double kr = 0.1, double kt = 0.9, double ior = 1.5)
        : base(ka, kd, cd, ks, exponent)
    {
        ReflectiveBrdf = new PerfectSpecular(kr);
        SpecularBtdf = new PerfectTransmitter(kt, ior);
        _split = new SplitScattering(ReflectiveBrdf, SpecularBtdf);
    }

    public PerfectSpecular ReflectiveBrdf { get; }
    public PerfectTransmitter SpecularBtdf { get; }

    protected override SpecularScattering Specular => _split;
}
