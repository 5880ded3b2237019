using RayTracer.Textures.Noise;

namespace RayTracer.Tests.Textures.Noise;

public class LatticeNoise_Values
{
    private static IEnumerable<(double X, double Y, double Z)> Points(int count, int seed)
    {
        var random = new Random(seed);
        for (var i = 0; i < count; i++)
            yield return (random.NextDouble() * 40 - 20, random.NextDouble() * 40 - 20, random.NextDouble() * 40 - 20);
    }

    public static TheoryData<string> Kinds => new() { "linear", "cubic" };

    private static LatticeNoise Make(string kind, int octaves = 1, int seed = 253) =>
        kind == "linear" ? new LinearNoise(octaves, seed: seed) : new CubicNoise(octaves, seed: seed);

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Interpolates_the_lattice_values_at_integer_points(string kind)
    {
        var noise = Make(kind);
        for (var i = -3; i < 4; i++)
        for (var j = -3; j < 4; j++)
            Assert.Equal(noise.LatticeValue(i, j, 2 * i - j), noise.ValueNoise(i, j, 2 * i - j), 12);
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Stays_in_range_is_periodic_and_depends_on_the_seed(string kind)
    {
        var a = Make(kind);
        var b = Make(kind, seed: 99);
        var differs = 0;
        foreach (var (x, y, z) in Points(500, 1))
        {
            var v = a.ValueNoise(x, y, z);
            Assert.InRange(v, -1.0, 1.0);
            Assert.Equal(v, a.ValueNoise(x + LatticeNoise.TableSize, y, z - LatticeNoise.TableSize), 9);
            if (Math.Abs(v - b.ValueNoise(x, y, z)) > 1e-6) differs++;
        }
        Assert.True(differs > 450, $"only {differs} of 500 values changed with the seed");
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Is_continuous_across_cell_faces(string kind)
    {
        var noise = Make(kind);
        foreach (var (_, y, z) in Points(50, 2))
            Assert.Equal(noise.ValueNoise(3 - 1e-9, y, z), noise.ValueNoise(3 + 1e-9, y, z), 6);
    }

    [Fact]
    public void Linear_noise_is_linear_along_a_lattice_edge()
    {
        var noise = new LinearNoise();
        var a = noise.LatticeValue(5, -2, 7);
        var b = noise.LatticeValue(6, -2, 7);
        foreach (var t in new[] { 0.1, 0.25, 0.5, 0.9 })
            Assert.Equal(a + t * (b - a), noise.ValueNoise(5 + t, -2, 7), 12);
    }

    [Fact]
    public void Cubic_noise_along_a_lattice_line_is_the_catmull_rom_spline()
    {
        var noise = new CubicNoise();
        double P(int i) => noise.LatticeValue(i, 4, -1);
        foreach (var t in new[] { 0.2, 0.5, 0.7 })
        {
            // Catmull-Rom in its matrix form: tangents (p2 - p0)/2 and (p3 - p1)/2 with Hermite basis.
            double p0 = P(9), p1 = P(10), p2 = P(11), p3 = P(12);
            double m1 = (p2 - p0) / 2, m2 = (p3 - p1) / 2;
            double h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t;
            double h01 = -2 * t * t * t + 3 * t * t, h11 = t * t * t - t * t;
            var expected = Math.Clamp(h00 * p1 + h10 * m1 + h01 * p2 + h11 * m2, -1, 1);
            Assert.Equal(expected, noise.ValueNoise(10 + t, 4, -1), 12);
        }
    }

    [Fact]
    public void Catmull_rom_reproduces_linear_data()
    {
        Assert.Equal(2.0 + 3.0 * 1.3, CubicNoise.CatmullRom(0.3, 2, 5, 8, 11), 12);
    }
}
