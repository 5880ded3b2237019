using RayTracer.BRDFs;
using RayTracer.BTDFs;
using RayTracer.Colors;
using RayTracer.Maths;

namespace RayTracer.Materials;

/// <summary>
/// Glass-like dielectric: Fresnel-weighted reflection and refraction, with Beer's-law colour filtering of
/// the light travelling inside (filter^distance) and outside (usually white) the object.
/// </summary>
public sealed class Dielectric : Phong
{
    private readonly FresnelScattering _fresnel;

    public Dielectric(double etaIn = 1.5, double etaOut = 1.0, RGBColor? filterInside = null, RGBColor? filterOutside = null,
        double ks = 0.2, double exponent = 2000)
        : base(0.0, 0.0, RGBColor.White, ks, exponent)
    {
        FresnelBrdf = new FresnelReflector(etaIn, etaOut);
        FresnelBtdf = new FresnelTransmitter(etaIn, etaOut);
        _fresnel = new FresnelScattering(FresnelBrdf, FresnelBtdf)
        {
            FilterInside = filterInside ?? RGBColor.White,
            FilterOutside = filterOutside ?? RGBColor.White,
        };
    }

    public FresnelReflector FresnelBrdf { get; }
    public FresnelTransmitter FresnelBtdf { get; }

    /// <summary>Fraction of each channel surviving one unit of distance inside the object.</summary>
    public RGBColor FilterInside
    {
        get => _fresnel.FilterInside;
        set => _fresnel.FilterInside = value;
    }

    public RGBColor FilterOutside
    {
        get => _fresnel.FilterOutside;
        set => _fresnel.FilterOutside = value;
    }

    protected override SpecularScattering Specular => _fresnel;

    /// <summary>Beer's law: a colour filter applied over a distance.</summary>
    public static RGBColor Attenuation(RGBColor filter, double distance) =>
        distance >= MathConstants.HugeValue ? RGBColor.White : filter.Pow(distance);
}
