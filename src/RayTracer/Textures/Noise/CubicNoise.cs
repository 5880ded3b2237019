namespace RayTracer.Textures.Noise;

/// <summary>
/// Value noise with tricubic Catmull-Rom interpolation over the 4x4x4 neighbouring lattice values:
/// smooth first derivatives across cells. The spline can overshoot, so results are clamped to [-1, 1].
/// </summary>
public sealed class CubicNoise : LatticeNoise
{
    public CubicNoise(int octaves = 1, double lacunarity = 2.0, double gain = 0.5, int seed = 253)
        : base(octaves, lacunarity, gain, seed)
    {
    }

    /// <summary>Catmull-Rom segment between <paramref name="p1"/> (t = 0) and <paramref name="p2"/> (t = 1).</summary>
    public static double CatmullRom(double t, double p0, double p1, double p2, double p3) =>
        0.5 * (2 * p1 + t * (-p0 + p2 + t * (2 * p0 - 5 * p1 + 4 * p2 - p3 + t * (-p0 + 3 * p1 - 3 * p2 + p3))));

    public override double ValueNoise(double x, double y, double z)
    {
        int ix = Floor(x), iy = Floor(y), iz = Floor(z);
        double fx = x - ix, fy = y - iy, fz = z - iz;

        Span<double> alongZ = stackalloc double[4];
        Span<double> alongY = stackalloc double[4];
        for (var k = 0; k < 4; k++)
        {
            for (var j = 0; j < 4; j++)
            {
                alongY[j] = CatmullRom(fx,
                    LatticeValue(ix - 1, iy + j - 1, iz + k - 1),
                    LatticeValue(ix, iy + j - 1, iz + k - 1),
                    LatticeValue(ix + 1, iy + j - 1, iz + k - 1),
                    LatticeValue(ix + 2, iy + j - 1, iz + k - 1));
            }
            alongZ[k] = CatmullRom(fy, alongY[0], alongY[1], alongY[2], alongY[3]);
        }
        return Math.Clamp(CatmullRom(fz, alongZ[0], alongZ[1], alongZ[2], alongZ[3]), -1.0, 1.0);
    }
}
