using GMac.Core.Algebra;
using GMac.Core.Numerics;

namespace GMac.Core.Tests.Algebra;

/// <summary>The frames every algebra identity is checked in.</summary>
internal static class TestFrames
{
    public static readonly Frame E2 = Frame.Euclidean("e2d", 2);
    public static readonly Frame E3 = Frame.Euclidean("e3d", 3);
    public static readonly Frame Cl41 = Frame.FromSignature("cl41", 4, 1);
    public static readonly Frame Conformal = Frame.Conformal3D();
    public static readonly Frame Projective = Frame.FromSignature("pga", 3, 0, 1);
    public static readonly Frame Spacetime = Frame.FromSignature("sta", 1, 3);

    /// <summary>A non-orthogonal, non-degenerate metric with no zero entries, to stress the general path.</summary>
    public static readonly Frame Skew = new("skew", ["a", "b", "c"], Metric.FromMatrix(new Rational[,]
    {
        { 2, 1, new Rational(1, 2) },
        { 1, -1, 3 },
        { new Rational(1, 2), 3, 1 },
    }));

    public static IEnumerable<object[]> All() =>
        new[] { E2, E3, Cl41, Conformal, Projective, Spacetime, Skew }.Select(f => new object[] { f.Name });

    public static IEnumerable<object[]> NonDegenerate() =>
        new[] { E2, E3, Cl41, Conformal, Spacetime, Skew }.Select(f => new object[] { f.Name });

    public static Frame ByName(string name) => name switch
    {
        "e2d" => E2,
        "e3d" => E3,
        "cl41" => Cl41,
        "cga5d" => Conformal,
        "pga" => Projective,
        "sta" => Spacetime,
        "skew" => Skew,
        _ => throw new ArgumentException(name),
    };
}
