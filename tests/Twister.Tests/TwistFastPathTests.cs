using Twister;

namespace Twister.Tests;

/// <summary>
/// The hot paths (coordinate-axis rotations, affine parameter maps folded at construction, the
/// cascade's direct calls) against Rodrigues' formula and against the same maps given as functions.
/// </summary>
public sealed class TwistFastPathTests
{
    private static readonly TwistablePoint Origin = new(0.4, -1.1, 0.7);

    public static TheoryData<double, double, double> CoordinateAxes() => new()
    {
        { 1, 0, 0 }, { -2, 0, 0 }, { 0, 0.5, 0 }, { 0, -1, 0 }, { 0, 0, 3 }, { 0, 0, -0.25 }, { 1, 2, -0.5 },
    };

    [Theory]
    [MemberData(nameof(CoordinateAxes))]
    public void Rotations_about_any_axis_in_either_sense_match_rodrigues(double ax, double ay, double az)
    {
        var axis = new TwistableVector(ax, ay, az);
        var twist = new RotationTwist(axis, Origin, 2.3, ParameterMap.Affine(1, -0.5, 0.2));
        var cascade = TwistCascade.Empty.Then(twist);
        var random = new Random(7);
        for (var i = 0; i < 20; i++)
        {
            var p = new TwistablePoint(random.NextDouble() * 4 - 2, random.NextDouble() * 4 - 2, random.NextDouble() * 4 - 2);
            var (u, v) = (random.NextDouble(), random.NextDouble());
            var expected = Rodrigues(p, axis, Origin, 2.3 * (u - 0.5 * v + 0.2));
            Near.Equal(expected, twist.Apply(p, u, v), 1e-12, $"rotation about {axis}");
            Near.Equal(expected, cascade.Apply(p, u, v), 1e-12, $"cascade of a rotation about {axis}");
            var (du, dv) = (new TwistableVector(), new TwistableVector());
            var moved = p;
            twist.ApplyWithTangents(ref moved, ref du, ref dv, u, v);
            Near.Equal(expected, moved, 1e-12, $"rotation about {axis} with tangents");
        }
    }

    [Fact]
    public void Full_twists_match_rodrigues_and_a_slide_along_the_axis()
    {
        var axis = new TwistableVector(-0.3, 0.4, 1.2);
        var twist = new FullTwist(axis, Origin, 5, ParameterMap.U, 0.7, ParameterMap.Affine(0.5, 1, -0.1));
        var cascade = TwistCascade.Empty.Then(twist);
        var p = new TwistablePoint(0.8, -0.3, 0.5);
        foreach (var (u, v) in new[] { (0.1, 0.9), (0.45, 0.2), (0.83, 0.61) })
        {
            var rotated = Rodrigues(p, axis, Origin, 5 * u);
            var slide = 0.7 * (0.5 * u + v - 0.1);
            var expected = new TwistablePoint(rotated.x + slide * axis.x, rotated.y + slide * axis.y, rotated.z + slide * axis.z);
            Near.Equal(expected, twist.Apply(p, u, v), 1e-12, $"full twist at ({u}, {v})");
            Near.Equal(expected, cascade.Apply(p, u, v), 1e-12, $"cascade of a full twist at ({u}, {v})");
        }
    }

    [Fact]
    public void Affine_maps_give_what_the_same_maps_given_as_functions_give()
    {
        var (a, b, c) = (1.3, -0.6, 0.25);
        var affine = ParameterMap.Affine(a, b, c);
        var function = ParameterMap.Of((u, v) => a * u + b * v + c, (_, _) => a, (_, _) => b);
        Twist[] Make(ParameterMap map) =>
        [
            new RotationTwist(new(1, 2, -0.5), Origin, 2.1, map),
            RotationTwist.AboutY(-1.4, map),
            new FullTwist(new(-0.3, 0.4, 1.2), Origin, 1.7, map, 0.8, map),
            new TranslationTwist(new(0.3, -1.2, 0.7), 1.5, map),
        ];
        var (fast, slow) = (new TwistCascade(Make(affine)), new TwistCascade(Make(function)));
        var seed = new TwistablePoint(0.9, -0.6, 1.3);
        foreach (var (u, v) in new[] { (0.0, 0.0), (0.3, 0.7), (0.95, 0.15) })
        {
            Near.Equal(slow.Apply(seed, u, v), fast.Apply(seed, u, v), 1e-12, $"point at ({u}, {v})");
            var expected = slow.ApplyWithTangents(seed, u, v, out var su, out var sv);
            var actual = fast.ApplyWithTangents(seed, u, v, out var fu, out var fv);
            Near.Equal(expected, actual, 1e-12, $"point with tangents at ({u}, {v})");
            Near.Equal(su, fu, 1e-12, $"∂/∂u at ({u}, {v})");
            Near.Equal(sv, fv, 1e-12, $"∂/∂v at ({u}, {v})");
        }
    }

    [Fact]
    public void One_tangent_kernels_give_the_u_tangent_of_the_two_tangent_kernels()
    {
        var cascade = TwistCascade.Empty
            .RotateAboutX(2 * Math.PI, ParameterMap.U)
            .RotateAbout(new(1, 2, -0.5), Origin, 3, ParameterMap.Affine(1, 0.4, 0.1))
            .Then(new FullTwist(new(-0.3, 0.4, 1.2), new(1, 0.5, -0.5), 5, ParameterMap.OfU(Math.Sin, Math.Cos), 0.7, ParameterMap.U))
            .Translate(new(0.2, 0.1, -0.3), 1.5, ParameterMap.Affine(-1, 2, 0));
        var seed = new TwistablePoint(0.8, -0.3, 0.5);
        foreach (var (u, v) in new[] { (0.1, 0.0), (0.55, 0.3), (0.9, 0.8) })
        {
            var expected = cascade.ApplyWithTangents(seed, u, v, out var du, out _);
            var actual = cascade.ApplyWithTangent(seed, u, v, out var tangent);
            Near.Equal(expected, actual, 1e-12, $"point at ({u}, {v})");
            Near.Equal(du, tangent, 1e-12, $"∂/∂u at ({u}, {v})");
            Near.Equal(Near.Difference(t => cascade.Apply(seed, t, v), u), tangent, 1e-6, $"∂/∂u against a central difference at ({u}, {v})");
        }
    }

    /// <summary>Rodrigues' rotation of p about the line through o along a (any length) by φ, right-handed.</summary>
    private static TwistablePoint Rodrigues(TwistablePoint p, TwistableVector a, TwistablePoint o, double angle)
    {
        var length = Math.Sqrt(Near.Dot(a, a));
        var k = new TwistableVector(a.x / length, a.y / length, a.z / length);
        var d = new TwistableVector(p.x - o.x, p.y - o.y, p.z - o.z);
        var (c, s) = (Math.Cos(angle), Math.Sin(angle));
        var kxd = Near.Cross(k, d);
        var f = Near.Dot(k, d) * (1 - c);
        return new(o.x + d.x * c + kxd.x * s + k.x * f, o.y + d.y * c + kxd.y * s + k.y * f, o.z + d.z * c + kxd.z * s + k.z * f);
    }
}
