using GMac.Benchmarks.Reporting;

namespace GMac.Benchmarks.Tests.Reporting;

public class RankCorrelation_Spearman
{
    [Fact]
    public void Any_increasing_map_gives_one_and_any_decreasing_map_minus_one()
    {
        double[] x = [3, 1, 4, 1.5, 9, 2.6];
        Assert.Equal(1, RankCorrelation.Spearman(x, x.Select(v => Math.Exp(v)).ToList()), 12);
        Assert.Equal(-1, RankCorrelation.Spearman(x, x.Select(v => -v * v * v).ToList()), 12);
    }

    [Fact]
    public void Without_ties_it_is_one_minus_six_times_the_squared_rank_differences_over_n_n2_minus_1()
    {
        double[] x = [10, 20, 30, 40, 50];
        double[] y = [2, 1, 4, 3, 5]; // rank differences 1, 1, 1, 1, 0
        Assert.Equal(1 - 6.0 * 4 / (5 * 24), RankCorrelation.Spearman(x, y), 12);
    }

    [Fact]
    public void Tied_values_share_the_mean_of_their_ranks()
    {
        Assert.Equal([1, 2.5, 2.5, 4], RankCorrelation.Ranks([1, 5, 5, 7]));
        Assert.Equal([3, 1.5, 1.5], RankCorrelation.Ranks([2, 0, 0]));
    }
}
