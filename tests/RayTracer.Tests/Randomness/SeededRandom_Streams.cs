using RayTracer.Randomness;

namespace RayTracer.Tests.Randomness;

public class SeededRandom_Streams
{
    [Fact]
    public void Same_seed_and_stream_give_the_same_sequence()
    {
        var a = new SeededRandom(42, 7);
        var b = new SeededRandom(1, 1);
        b.Reseed(42, 7);
        for (int i = 0; i < 100; i++)
        {
            Assert.Equal(a.NextULong(), b.NextULong());
        }
    }

    [Fact]
    public void Neighbouring_streams_differ()
    {
        var a = new SeededRandom(42, 7);
        var b = new SeededRandom(42, 8);
        int equal = 0;
        for (int i = 0; i < 100; i++)
        {
            equal += a.NextULong() == b.NextULong() ? 1 : 0;
        }

        Assert.Equal(0, equal);
    }

    [Fact]
    public void Doubles_are_in_the_unit_interval_with_uniform_moments()
    {
        var random = new SeededRandom(3);
        const int n = 200_000;
        double sum = 0, sumSq = 0;
        for (int i = 0; i < n; i++)
        {
            double x = random.NextDouble();
            Assert.InRange(x, 0.0, 0.9999999999999999);
            sum += x;
            sumSq += x * x;
        }

        // Mean 1/2 and second moment 1/3; bounds are about 6 standard errors.
        Assert.InRange(sum / n, 0.5 - 0.004, 0.5 + 0.004);
        Assert.InRange(sumSq / n, 1.0 / 3 - 0.004, 1.0 / 3 + 0.004);
    }

    [Fact]
    public void Integers_cover_the_range_evenly()
    {
        var random = new SeededRandom(4);
        var counts = new int[7];
        for (int i = 0; i < 70_000; i++)
        {
            counts[random.NextInt(7)]++;
        }

        // Expected 10 000 each, standard deviation about 93.
        Assert.All(counts, c => Assert.InRange(c, 9400, 10600));
    }

    [Fact]
    public void Shuffle_is_a_permutation()
    {
        var random = new SeededRandom(5);
        int[] items = Enumerable.Range(0, 50).ToArray();
        random.Shuffle<int>(items);
        Assert.Equal(Enumerable.Range(0, 50), items.OrderBy(x => x));
        Assert.NotEqual(Enumerable.Range(0, 50), items);
    }
}
