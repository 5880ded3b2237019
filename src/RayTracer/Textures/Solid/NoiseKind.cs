namespace RayTracer.Textures.Solid;

/// <summary>Which function of a lattice noise a noise texture shows.</summary>
public enum NoiseKind
{
    /// <summary>Single octave, mapped from [-1, 1] to [0, 1].</summary>
    Value,
    Fbm,
    Turbulence,
    WrappedFbm,
}
