using RayTracer.BRDFs;
using RayTracer.Colors;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// How a surface scatters light at one hit, as an integrator sees it: a diffuse (Lambertian) lobe and a Phong
/// highlight, evaluated towards lights (<see cref="F"/>); and specular lobes (mirror, blurred mirror,
/// refraction), which only a traced ray can follow (<see cref="SampleSpecular"/>). A path bounce
/// (<see cref="SampleBounce"/>) follows the specular lobes when there are any, and the diffuse lobe otherwise.
/// A value made per hit from lobes the material owns, so building one allocates nothing.
/// </summary>
public readonly struct Bsdf
{
    private readonly ShadingRecord? _sr;

    public Bsdf(ShadingRecord sr, Lambertian? diffuse, GlossySpecular? highlight = null, SpecularScattering? specular = null)
    {
        _sr = sr;
        Diffuse = diffuse;
        Highlight = highlight;
        Specular = specular;
    }

    /// <summary>The BSDF of a surface that does not scatter (an emitter).</summary>
    public static Bsdf None => default;

    public Lambertian? Diffuse { get; }
    public GlossySpecular? Highlight { get; }
    public SpecularScattering? Specular { get; }

    /// <summary>True for a surface that scatters no light (it may emit).</summary>
    public bool IsEmpty => Diffuse is null && Highlight is null && Specular is null;

    /// <summary>True when some lobe has a value towards a light (direct lighting applies).</summary>
    public bool MeetsLights => Diffuse is not null || Highlight is not null;

    public bool HasSpecular => Specular is not null;

    /// <summary>True when some light passes through the surface.</summary>
    public bool Transmits => Specular?.Transmits ?? false;

    private ShadingRecord Record => _sr ?? throw new InvalidOperationException("This BSDF belongs to no hit.");

    /// <summary>f(wo, wi) of the lobes that meet lights (black for the specular lobes, whose f is a delta).</summary>
    public RGBColor F(Vector3D wo, Vector3D wi)
    {
        var sr = Record;
        if (Highlight is null)
            return Diffuse is null ? RGBColor.Black : Diffuse.F(sr, wo, wi);
        return Diffuse is null ? Highlight.F(sr, wo, wi) : Diffuse.F(sr, wo, wi) + Highlight.F(sr, wo, wi);
    }

    /// <summary>
    /// Solid-angle density with which <see cref="SampleBounce"/> draws <paramref name="wi"/>: cosine-weighted
    /// for a diffuse bounce, 0 where only specular lobes are followed (a delta has no density).
    /// </summary>
    public double Pdf(Vector3D wo, Vector3D wi) =>
        Specular is null && Diffuse is not null ? Diffuse.Pdf(Record, wo, wi) : 0.0;

    /// <summary>The specular lobes' rays (none without specular lobes).</summary>
    public int SampleSpecular(Vector3D wo, Span<BsdfSample> samples) =>
        Specular is null ? 0 : Specular.Sample(Record, wo, samples);

    /// <summary>One path bounce: the specular lobes' rays, or else one cosine-weighted diffuse direction.</summary>
    public int SampleBounce(Vector3D wo, Span<BsdfSample> samples)
    {
        if (Specular is not null)
            return Specular.Sample(Record, wo, samples);
        if (Diffuse is null)
            return 0;
        var sr = Record;
        var f = Diffuse.SampleF(sr, wo, out var wi, out var pdf);
        var ndotwi = sr.Normal.Dot(wi);
        if (pdf <= 0 || ndotwi <= 0)
            return 0;
        samples[0] = new BsdfSample(wi, f, ndotwi, pdf);
        return 1;
    }
}
