using Twister;

namespace Twister.Tests;

/// <summary>Twists applied to twists, points, directions and tangent planes, checked against each other.</summary>
public sealed class TwistOfTwistTests
{
    private const double U = 0.37, V = 0.81;

    private static readonly string[] KindNames = ["translation", "rotation", "full", "reflection", "scaling", "null"];

    public static TheoryData<string> Kinds() => new(KindNames);

    private static Twist Make(string kind) => kind switch
    {
        "translation" => new TranslationTwist(new(0.3, -1.2, 0.7), 1.5, ParameterMap.Affine(1, -0.5, 0.25)),
        "rotation" => new RotationTwist(new(1, 2, -0.5), new(0.2, -0.4, 1), 2.1, ParameterMap.Affine(0.5, 1, 0.1)),
        "full" => new FullTwist(new(-0.3, 0.4, 1.2), new(1, 0.5, -0.5), 1.7, ParameterMap.U, 0.8, ParameterMap.V),
        "reflection" => new ReflectionTwist(new(0.5, 0.5, -1), new(1, -1, 2)),
        "scaling" => new ScalingTwist(new(-1, 0.3, 0.2), 0.6, ParameterMap.Affine(1, 1, -0.5)),
        _ => NullTwist.Instance,
    };

    private static readonly TwistablePoint P = new(0.9, -0.6, 1.3);

    private static TwistablePoint Offset(TwistablePoint p, TwistableVector d, double s) => new(p.x + s * d.x, p.y + s * d.y, p.z + s * d.z);

    [Theory]
    [MemberData(nameof(Kinds))]
    public void A_twist_applied_to_a_twist_then_to_the_moved_point_equals_both_in_turn(string kind)
    {
        foreach (var inner in KindNames)
        {
            var by = Make(kind);
            var other = Make(inner);
            var moved = by.Apply(other, U, V);
            // by ∘ other ∘ by⁻¹ applied to by(p) is by(other(p)).
            var expected = by.Apply(other.Apply(P, 0.2, 0.6), U, V);
            var actual = moved.Apply(by.Apply(P, U, V), 0.2, 0.6);
            Near.Equal(expected, actual, 1e-12, $"{kind} applied to {inner}");
        }
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void A_direction_moves_as_the_difference_of_two_moved_points(string kind)
    {
        var twist = Make(kind);
        var d = new TwistableVector(0.4, 1.1, -0.8);
        var (a, b) = (twist.Apply(P, U, V), twist.Apply(Offset(P, d, 1), U, V));
        Near.Equal(new TwistableVector(b.x - a.x, b.y - a.y, b.z - a.z), twist.Apply(d, U, V), 1e-12, kind);
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void A_tangent_plane_moves_as_the_two_tangents_spanning_it(string kind)
    {
        var twist = Make(kind);
        TwistableVector a = new(0.4, 1.1, -0.8), b = new(-1, 0.3, 0.5);
        var expected = TwistableBivector.Span(twist.Apply(a, U, V), twist.Apply(b, U, V));
        Near.Equal(expected, twist.Apply(TwistableBivector.Span(a, b), U, V), 1e-12, kind);
    }

    [Theory]
    [MemberData(nameof(Kinds))]
    public void Tangents_of_one_twist_equal_central_differences(string kind)
    {
        var twist = Make(kind);
        var cascade = new TwistCascade(Make("rotation"), twist);
        var seed = new TwistablePoint(0.1, 0.2, -0.3);
        cascade.ApplyWithTangents(seed, U, V, out var du, out var dv);
        Near.Equal(Near.Difference(u => cascade.Apply(seed, u, V), U), du, 1e-6, $"{kind} ∂/∂u");
        Near.Equal(Near.Difference(v => cascade.Apply(seed, U, v), V), dv, 1e-6, $"{kind} ∂/∂v");
    }

    [Fact]
    public void A_user_map_drives_tangents_through_its_derivatives()
    {
        var map = ParameterMap.Of((u, v) => Math.Sin(3 * u) * v * v, (u, v) => 3 * Math.Cos(3 * u) * v * v, (u, v) => 2 * Math.Sin(3 * u) * v);
        var cascade = TwistCascade.Empty.RotateAbout(new(0, 1, 1), new(1, 0, 0), 1.3, map).Then(new ScalingTwist(default, 0.4, map));
        var seed = new TwistablePoint(0.5, 0.5, 0.5);
        cascade.ApplyWithTangents(seed, U, V, out var du, out var dv);
        Near.Equal(Near.Difference(u => cascade.Apply(seed, u, V), U), du, 1e-6, "∂/∂u");
        Near.Equal(Near.Difference(v => cascade.Apply(seed, U, v), V), dv, 1e-6, "∂/∂v");
    }

    [Fact]
    public void Rotating_a_cascade_about_z_rotates_its_curve()
    {
        var circle = TwistCurves.Circle(new(1, 0, 0), 0.5);
        var quarter = RotationTwist.AboutZ(Math.PI / 2, ParameterMap.One);
        var turned = new TwistCurve(quarter.Apply(circle.Seed, 0, 0), circle.Cascade.TransformedBy(quarter));
        foreach (var t in new[] { 0.1, 0.45, 0.8 })
        {
            var p = circle.PointAt(t);
            Near.Equal(new TwistablePoint(-p.y, p.x, p.z), turned.PointAt(t), 1e-12, $"t = {t}");
        }
    }

    [Fact]
    public void Rotated_about_x_moves_a_rotation_axis()
    {
        var twist = (RotationTwist)RotationTwist.AboutZ(1, ParameterMap.U).RotatedAboutX(Math.PI / 2);
        Near.Equal(new TwistableVector(0, -1, 0), twist.Axis, 1e-12, "axis");
    }
}
