using RayTracer.Maths;
using RayTracer.Textures.Noise;

namespace RayTracer.Textures.Solid;

/// <summary>Scalar solid texture in [0, 1] from a lattice noise; colour it with a conversion texture.</summary>
public sealed class NoiseTexture(LatticeNoise noise, NoiseKind kind = NoiseKind.Fbm, double scale = 1.0, double expansion = 8.0)
    : SolidTexture<double>
{
    public LatticeNoise Noise { get; } = noise;
    public NoiseKind Kind { get; set; } = kind;

    /// <summary>Frequency multiplier applied to the hit point.</summary>
    public double Scale { get; set; } = scale;

    /// <summary>Number of bands of wrapped fBm.</summary>
    public double Expansion { get; set; } = expansion;

    public override double Evaluate(Point3D p)
    {
        double x = p.x * Scale, y = p.y * Scale, z = p.z * Scale;
        return Kind switch
        {
            NoiseKind.Value => 0.5 * (Noise.ValueNoise(x, y, z) + 1),
            NoiseKind.Turbulence => Noise.Turbulence(x, y, z),
            NoiseKind.WrappedFbm => Noise.WrappedFbm(x, y, z, Expansion),
            _ => Noise.Fbm(x, y, z),
        };
    }
}
