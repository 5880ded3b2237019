using GMac.CSharp.Tests.Support;
using Twister;

namespace GMac.Cli.Tests.Twister;

/// <summary>
/// Twister's FullTwist, whose kernels are generated from dsl/macros/twister.gmac, against an independent
/// construction: Rodrigues' rotation about the line, then a slide along the axis. The body under
/// test is the committed one, so one test first checks that it is what gmac generates today.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Twist_MatchesRodrigues
{
    [Fact]
    public void The_committed_full_twist_is_what_gmac_generates_from_the_library()
    {
        var twist = Path.Combine(SharedDsl.RepositoryRoot, "src", "Twister", "FullTwist.cs");
        var text = File.ReadAllText(twist);
        Assert.Contains("#region GMac : FullTwistPoint", text);
        var regions = text.Split('\n').Count(line => line.TrimStart().StartsWith("#region GMac :", StringComparison.Ordinal));
        var (exit, output, error) = Tool.Generate([twist], check: true);
        Assert.True(exit == 0, output + error);
        Assert.Contains($"{regions} region(s)", output);
    }

    private static TwistablePoint Expected(TwistablePoint origin, TwistablePoint axis, double angle, double slide, TwistablePoint p)
    {
        var length = Math.Sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
        double kx = axis.x / length, ky = axis.y / length, kz = axis.z / length;
        double vx = p.x - origin.x, vy = p.y - origin.y, vz = p.z - origin.z;
        double c = Math.Cos(angle), s = Math.Sin(angle), dot = kx * vx + ky * vy + kz * vz;
        var rx = vx * c + (ky * vz - kz * vy) * s + kx * dot * (1 - c);
        var ry = vy * c + (kz * vx - kx * vz) * s + ky * dot * (1 - c);
        var rz = vz * c + (kx * vy - ky * vx) * s + kz * dot * (1 - c);
        return new TwistablePoint(rx + origin.x + slide * axis.x, ry + origin.y + slide * axis.y, rz + origin.z + slide * axis.z);
    }

    [Fact]
    public void Random_twists_of_random_points()
    {
        var random = new Random(42);
        double R() => random.NextDouble() * 4 - 2;
        for (var i = 0; i < 50; i++)
        {
            var origin = new TwistablePoint(R(), R(), R());
            var axis = new TwistablePoint(R(), R(), R());
            var (angle, slide) = (R() * 3, R());
            var p = new TwistablePoint(R(), R(), R());

            var actual = new FullTwist(new(axis.x, axis.y, axis.z), origin, angle, slide).Apply(p, 0, 0);
            var expected = Expected(origin, axis, angle, slide, p);

            Assert.Equal(expected.x, actual.x, 1e-9);
            Assert.Equal(expected.y, actual.y, 1e-9);
            Assert.Equal(expected.z, actual.z, 1e-9);
        }
    }

    [Fact]
    public void Quarter_turn_about_z_through_a_point_then_slide()
    {
        var twist = new FullTwist(new TwistableVector(0, 0, 1), new TwistablePoint(1, 0, 0), Math.PI / 2, 3);
        var moved = twist.Apply(new TwistablePoint(2, 0, 5), 0, 0);
        Assert.Equal(1, moved.x, 1e-12);
        Assert.Equal(1, moved.y, 1e-12);
        Assert.Equal(8, moved.z, 1e-12);
    }
}
