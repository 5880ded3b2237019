using RayTracer.Colors;
using RayTracer.Maths;

namespace RayTracer.Materials;

/// <summary>
/// A direction drawn from a BSDF: the incident direction <see cref="Wi"/>, the BSDF's value <see cref="F"/> for
/// it, the cosine the estimator weights it by and its density (1 for a delta lobe, whose f already has the
/// cosine divided out). The radiance it brings back is f·Li·(cos / pdf). A sample that crosses into or out of
/// an absorbing medium carries that medium's <see cref="Filter"/> (Beer's law over the distance travelled).
/// </summary>
public readonly record struct BsdfSample(Vector3D Wi, RGBColor F, double Cos, double Pdf)
{
    /// <summary>True when the light along <see cref="Wi"/> is filtered by <see cref="Filter"/> per unit distance.</summary>
    public bool Absorbs { get; init; }

    /// <summary>Fraction of each channel surviving one unit of distance along <see cref="Wi"/>.</summary>
    public RGBColor Filter { get; init; }

    /// <summary>cos / pdf: the estimator's weight of f·Li.</summary>
    public double Weight => Cos / Pdf;
}
