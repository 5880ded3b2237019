using RayTracer.Cli;
using RayTracer.Colors;

namespace RayTracer.Tests.Cli;

public class Application_Snapshot : CommandLineTest
{
    [Fact]
    public void A_second_snapshot_with_the_same_seed_is_identical_and_another_seed_differs()
    {
        var first = Path.Combine(Dir, "first");
        var (code, _, err) = Run("snapshot", "-o", first, "--scene", "spheres", "--scene", "light-area-disk", "--width", "8", "--height", "6");
        Assert.True(code == 0, err);
        Assert.True(File.Exists(Path.Combine(first, "light-area-disk.bin")));

        var (same, output, _) = Run("snapshot", "-o", Path.Combine(Dir, "again"), "--against", first,
            "--scene", "spheres", "--scene", "light-area-disk", "--width", "8", "--height", "6");
        Assert.Equal(0, same);
        Assert.Contains("2 of 2 identical", output);

        var (_, reseeded, _) = Run("snapshot", "-o", Path.Combine(Dir, "other"), "--against", first,
            "--scene", "light-area-disk", "--width", "8", "--height", "6", "--seed", "99");
        Assert.Contains("differs", reseeded);
        Assert.Contains("0 of 1 identical", reseeded);
    }

    [Fact]
    public void Difference_statistics_match_a_hand_computation()
    {
        RGBColor[] a = [new(1, 0, 0), new(3, 0, 0)];
        RGBColor[] b = [new(0, 0, 0), new(0, 0, 1)];
        var d = SceneSnapshot.Difference(a, b);
        // Red differences 1 and 3: mean 2, sample variance 2, standard error sqrt(2/2) = 1.
        Assert.Equal(2.0, d[0].MeanAbsolute, 12);
        Assert.Equal(2.0, d[0].Mean, 12);
        Assert.Equal(1.0, d[0].StandardError, 12);
        Assert.Equal(0.5, d[2].MeanAbsolute, 12);
        Assert.Equal(-0.5, d[2].Mean, 12);
    }
}
