using GMac.Benchmarks.Applications;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Values;

namespace GMac.Benchmarks.Tests.Kernels;

/// <summary>The accurate hand forms timed against the textbook ones compute the same results on well-conditioned inputs.</summary>
public class AccurateForms_AgreeWithHand
{
    private static Vec3 Next(Random random) => new(random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1);

    private static void Close(double expected, double actual) =>
        Assert.True(Math.Abs(expected - actual) <= 1e-9 * Math.Max(1, Math.Abs(expected)), $"{expected} vs {actual}");

    [Fact]
    public void Accurate_rejection_gives_the_textbook_orthogonal_vectors()
    {
        var random = new Random(4);
        for (var i = 0; i < 200; i++)
        {
            var v = new Vec3Triple { A = Next(random), B = Next(random), C = Next(random) };
            GramSchmidtRejectionKernel.Hand(in v, out var hand);
            AccurateFormBenchmarks.AccurateRejection(in v, out var accurate);
            foreach (var (h, a) in new[] { (hand.A, accurate.A), (hand.B, accurate.B), (hand.C, accurate.C) })
            {
                Close(h.x, a.x);
                Close(h.y, a.y);
                Close(h.z, a.z);
            }
        }
    }

    [Fact]
    public void Accurate_skew_lines_give_the_textbook_parameters()
    {
        var random = new Random(5);
        for (var i = 0; i < 200; i++)
        {
            var l = new LinePair { P1 = Next(random), D1 = Next(random), P2 = Next(random), D2 = Next(random) };
            SkewLinesClosestPointsKernel.Hand(in l, out var hand);
            AccurateFormBenchmarks.AccurateSkewLines(in l, out var accurate);
            Close(hand.T1, accurate.T1);
            Close(hand.T2, accurate.T2);
        }
    }
}
