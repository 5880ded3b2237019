using RayTracer.Maths;
using RayTracer.Sampling;

namespace RayTracer.Tests.Sampling;

public class Samplers_Stratification
{
    private static IEnumerable<Point2D[]> Sets(Sampler sampler)
    {
        var all = sampler.SquareSamples.ToArray();
        for (var s = 0; s < sampler.NumSets; s++)
            yield return all.Skip(s * sampler.NumSamples).Take(sampler.NumSamples).ToArray();
    }

    private static void AssertOnePerCell(Point2D[] set, int nx, int ny)
    {
        var counts = new int[nx, ny];
        foreach (var p in set)
        {
            Assert.InRange(p.x, 0.0, 1.0 - 1e-15);
            Assert.InRange(p.y, 0.0, 1.0 - 1e-15);
            counts[(int)(p.x * nx), (int)(p.y * ny)]++;
        }
        foreach (var c in counts)
            Assert.Equal(1, c);
    }

    [Fact]
    public void Jittered_has_one_sample_per_grid_cell()
    {
        var sampler = new JitteredSampler(16, numSets: 10);
        Assert.Equal(16, sampler.NumSamples);
        foreach (var set in Sets(sampler))
            AssertOnePerCell(set, 4, 4);
    }

    [Fact]
    public void N_rooks_has_one_sample_per_row_and_per_column()
    {
        var sampler = new NRooksSampler(7, numSets: 10);
        foreach (var set in Sets(sampler))
        {
            AssertOnePerCell(set, 7, 1);
            AssertOnePerCell(set, 1, 7);
        }
    }

    [Fact]
    public void Multi_jittered_is_jittered_and_n_rooks_on_the_fine_grid()
    {
        var sampler = new MultiJitteredSampler(25, numSets: 10);
        foreach (var set in Sets(sampler))
        {
            AssertOnePerCell(set, 5, 5);
            AssertOnePerCell(set, 25, 1);
            AssertOnePerCell(set, 1, 25);
        }
    }

    [Fact]
    public void Regular_uses_cell_centres()
    {
        var sampler = new RegularSampler(10); // rounded down to 9
        Assert.Equal(9, sampler.NumSamples);
        var set = Sets(sampler).Single();
        AssertOnePerCell(set, 3, 3);
        Assert.All(set, p => Assert.Equal(0.5, (p.x * 3) % 1.0, 12));
    }

    [Fact]
    public void Hammersley_is_i_over_n_against_the_base_2_radical_inverse()
    {
        var set = Sets(new HammersleySampler(8)).Single();
        var expectedY = new[] { 0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875 };
        for (var i = 0; i < 8; i++)
        {
            Assert.Equal(i / 8.0, set[i].x, 15);
            Assert.Equal(expectedY[i], set[i].y, 15);
        }
        AssertOnePerCell(set, 8, 1);
        AssertOnePerCell(set, 1, 8);
    }

    [Fact]
    public void A_pixel_draws_a_whole_set_in_shuffled_order()
    {
        var sampler = new JitteredSampler(9, numSets: 5);
        SamplingContext.BeginPixel(42, 7);
        var drawn = Enumerable.Range(0, 9).Select(_ => sampler.SampleUnitSquare()).ToArray();
        Assert.Contains(Sets(sampler), set => set.OrderBy(p => p.x).ThenBy(p => p.y)
            .SequenceEqual(drawn.OrderBy(p => p.x).ThenBy(p => p.y)));
    }

    [Fact]
    public async Task Samples_depend_only_on_seed_and_pixel()
    {
        var sampler = new MultiJitteredSampler(16);
        Point2D[] Draw(ulong pixel)
        {
            SamplingContext.BeginPixel(5, pixel);
            return Enumerable.Range(0, 40).Select(_ => sampler.SampleUnitSquare()).ToArray();
        }
        var first = Draw(3);
        Draw(4);
        Assert.Equal(first, Draw(3));
        var onOtherThread = await Task.Run(() => Draw(3));
        Assert.Equal(first, onOtherThread);
    }

    [Fact]
    public void Invalid_counts_are_rejected()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => new PureRandomSampler(0));
        Assert.Throws<ArgumentOutOfRangeException>(() => new JitteredSampler(4, numSets: 0));
    }
}
