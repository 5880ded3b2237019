using RayTracer.Tracing;

namespace RayTracer.Tests.Tracing;

public class InvocationCounter_Totals
{
    [Fact]
    public void Counts_from_many_threads_are_summed_exactly()
    {
        var a = new InvocationCounter("a");
        var b = new InvocationCounter("b");
        Parallel.For(0, 8, new ParallelOptions { MaxDegreeOfParallelism = 4 }, i =>
        {
            for (var k = 0; k < 10_000; k++)
                a.Increment();
            // A counter created while threads already count must grow their slots without losing counts.
            var late = new InvocationCounter($"late {i}");
            late.Increment();
            for (var k = 0; k <= i; k++)
                b.Increment();
            Assert.Equal(1, late.Total);
        });
        Assert.Equal(80_000, a.Total);
        Assert.Equal(36, b.Total);
    }

    [Fact]
    public void Reset_sets_one_counter_to_zero_and_leaves_the_others()
    {
        var a = new InvocationCounter("a");
        var b = new InvocationCounter("b");
        a.Increment();
        b.Increment();
        b.Increment();
        a.Reset();
        Assert.Equal(0, a.Total);
        Assert.Equal(2, b.Total);
        Assert.Contains(b, InvocationCounter.All);
    }
}
