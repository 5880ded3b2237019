namespace RayTracer.Textures.Noise;

/// <summary>Value noise with trilinear interpolation between the eight surrounding lattice values.</summary>
public sealed class LinearNoise : LatticeNoise
{
    public LinearNoise(int octaves = 1, double lacunarity = 2.0, double gain = 0.5, int seed = 253)
        : base(octaves, lacunarity, gain, seed)
    {
    }

    public override double ValueNoise(double x, double y, double z)
    {
        int ix = Floor(x), iy = Floor(y), iz = Floor(z);
        double fx = x - ix, fy = y - iy, fz = z - iz;

        double Lerp(double t, double a, double b) => a + t * (b - a);
        double Edge(int j, int k) => Lerp(fx, LatticeValue(ix, iy + j, iz + k), LatticeValue(ix + 1, iy + j, iz + k));

        var y0 = Lerp(fy, Edge(0, 0), Edge(1, 0));
        var y1 = Lerp(fy, Edge(0, 1), Edge(1, 1));
        return Lerp(fz, y0, y1);
    }
}
