using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Materials;

/// <summary>
/// The lobes of a BSDF that integrators follow by tracing a ray rather than by meeting lights: a perfect
/// mirror, a blurred (sampled Phong) reflection, or a reflection and a transmission split at an interface.
/// </summary>
public abstract class SpecularScattering
{
    /// <summary>Largest number of samples <see cref="Sample"/> writes.</summary>
    public const int MaxSamples = 2;

    /// <summary>True when some light passes through the surface.</summary>
    public virtual bool Transmits => false;

    /// <summary>Writes the directions to trace from the hit seen along <paramref name="wo"/>; returns how many.</summary>
    public abstract int Sample(ShadingRecord sr, Vector3D wo, Span<BsdfSample> samples);
}
