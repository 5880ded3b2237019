using RayTracer.Textures.Noise;

namespace RayTracer.Tests.Textures.Noise;

public class LatticeNoise_Fractals
{
    [Fact]
    public void Fbm_is_the_normalised_octave_sum()
    {
        var one = new LinearNoise(octaves: 1);
        var three = new LinearNoise(octaves: 3, lacunarity: 2.0, gain: 0.5);
        var random = new Random(3);
        for (var n = 0; n < 200; n++)
        {
            double x = random.NextDouble() * 10, y = random.NextDouble() * 10, z = random.NextDouble() * 10;
            var sum = one.ValueNoise(x, y, z) + 0.5 * one.ValueNoise(2 * x, 2 * y, 2 * z) + 0.25 * one.ValueNoise(4 * x, 4 * y, 4 * z);
            Assert.Equal(sum, three.FractalSum(x, y, z), 12);
            // Amplitudes 1 + 0.5 + 0.25 bound the sum, so fBm maps [-1.75, 1.75] onto [0, 1].
            Assert.Equal((sum + 1.75) / 3.5, three.Fbm(x, y, z), 12);
            Assert.InRange(three.Fbm(x, y, z), 0.0, 1.0);

            var turbulence = Math.Abs(one.ValueNoise(x, y, z)) + 0.5 * Math.Abs(one.ValueNoise(2 * x, 2 * y, 2 * z))
                + 0.25 * Math.Abs(one.ValueNoise(4 * x, 4 * y, 4 * z));
            Assert.Equal(turbulence / 1.75, three.Turbulence(x, y, z), 12);
            Assert.InRange(three.Turbulence(x, y, z), 0.0, 1.0);
        }
    }

    [Fact]
    public void Wrapped_fbm_is_the_fractional_part_of_the_expanded_fbm()
    {
        var noise = new CubicNoise(octaves: 4);
        var random = new Random(4);
        for (var n = 0; n < 200; n++)
        {
            double x = random.NextDouble() * 10, y = random.NextDouble() * 10, z = random.NextDouble() * 10;
            var expanded = 7.0 * noise.Fbm(x, y, z);
            var wrapped = noise.WrappedFbm(x, y, z, 7.0);
            Assert.InRange(wrapped, 0.0, 1.0 - 1e-15);
            Assert.Equal(expanded - Math.Floor(expanded), wrapped, 12);
        }
    }

    [Fact]
    public void Noise_is_not_constant()
    {
        var noise = new LinearNoise();
        var values = Enumerable.Range(0, 100).Select(i => noise.ValueNoise(i * 0.37, i * 0.11, i * 0.53)).ToList();
        Assert.True(values.Max() - values.Min() > 0.5);
        Assert.True(Math.Abs(values.Average()) < 0.3);
    }
}
