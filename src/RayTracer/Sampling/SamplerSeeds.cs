namespace RayTracer.Sampling;

/// <summary>
/// Fixed seeds for the sample sets of each role. Samplers of the same kind and size built from one seed hold
/// identical sets, and pairing pixel sample i with lens or light sample i from an identical set correlates
/// them (visible as structured noise); distinct seeds per role avoid that while keeping images reproducible.
/// </summary>
public static class SamplerSeeds
{
    public const ulong Pixel = 0x5049584Cu;
    public const ulong Lens = 0x4C454E53u;
    public const ulong Diffuse = 0x44494646u;
    public const ulong Glossy = 0x474C4F53u;
    public const ulong AmbientOcclusion = 0x414F4343u;
    public const ulong Environment = 0x454E5649u;

    /// <summary>Base for area lights; each light adds its index so two lights do not share sets.</summary>
    public const ulong AreaLight = 0x41524541u;
}
