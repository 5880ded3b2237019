using RayTracer.Maths;
using RayTracer.Sampling;

namespace RayTracer.Tests.Sampling;

public class Samplers_Mappings
{
    [Fact]
    public void Disk_samples_lie_in_the_disk_and_are_uniform_in_area()
    {
        var sampler = new PureRandomSampler(100, numSets: 200);
        sampler.MapSamplesToUnitDisk();
        var disk = sampler.DiskSamples.ToArray();
        Assert.All(disk, p => Assert.True(p.x * p.x + p.y * p.y <= 1.0 + 1e-12));
        // Area fraction within radius 1/2 is 1/4; within the right half-plane 1/2.
        var n = disk.Length;
        var inner = disk.Count(p => p.x * p.x + p.y * p.y < 0.25) / (double)n;
        var right = disk.Count(p => p.x > 0) / (double)n;
        var sigma = Math.Sqrt(0.25 * 0.75 / n);
        Assert.InRange(inner, 0.25 - 4 * sigma, 0.25 + 4 * sigma);
        Assert.InRange(right, 0.5 - 4 * 0.5 / Math.Sqrt(n), 0.5 + 4 * 0.5 / Math.Sqrt(n));
    }

    [Fact]
    public void Concentric_map_sends_square_corners_and_edges_to_the_circle()
    {
        var corner = Sampler.ConcentricDisk(new Point2D(1, 1));
        Assert.Equal(1.0, Math.Sqrt(corner.x * corner.x + corner.y * corner.y), 12);
        var centre = Sampler.ConcentricDisk(new Point2D(0.5, 0.5));
        Assert.Equal(0.0, centre.x, 15);
        Assert.Equal(0.0, centre.y, 15);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(1.0)]
    [InlineData(5.0)]
    [InlineData(100.0)]
    public void Hemisphere_samples_have_the_cosine_power_mean(double e)
    {
        var sampler = new MultiJitteredSampler(64, numSets: 100);
        sampler.MapSamplesToHemisphere(e);
        var samples = sampler.HemisphereSamples.ToArray();
        Assert.All(samples, v =>
        {
            Assert.Equal(1.0, v.Length, 9);
            Assert.True(v.z >= 0);
        });
        // For density ∝ cos^e θ on the hemisphere, E[cos θ] = (e + 1) / (e + 2).
        var mean = samples.Average(v => v.z);
        Assert.Equal((e + 1) / (e + 2), mean, 2);
        // Azimuthal symmetry.
        Assert.Equal(0.0, samples.Average(v => v.x), 2);
        Assert.Equal(0.0, samples.Average(v => v.y), 2);
    }

    [Fact]
    public void Sphere_samples_are_unit_and_isotropic()
    {
        var sampler = new JitteredSampler(64, numSets: 100);
        sampler.MapSamplesToSphere();
        var samples = sampler.SphereSamples.ToArray();
        Assert.All(samples, v => Assert.Equal(1.0, v.Length, 9));
        Assert.Equal(0.0, samples.Average(v => v.z), 2);
        Assert.Equal(1.0 / 3.0, samples.Average(v => v.x * v.x), 2);
        Assert.Equal(1.0 / 3.0, samples.Average(v => v.z * v.z), 2);
    }

    [Fact]
    public void Unmapped_samples_are_reported()
    {
        var sampler = new JitteredSampler(4);
        Assert.Throws<InvalidOperationException>(() => sampler.SampleUnitDisk());
    }
}
