using GMac.Benchmarks.Kernels.Values;
using GMac.Core.Algebra;

namespace GMac.Benchmarks.Kernels;

/// <summary>
/// The frames and blades of the direct variant, built once, and conversions between the
/// benchmark structs and <c>Multivector&lt;double&gt;</c>.
/// </summary>
public static class DirectAlgebra
{
    public static readonly Frame E2 = Frame.Euclidean("e2d", 2);
    public static readonly Frame E3 = Frame.Euclidean("e3d", 3);
    public static readonly Frame Cga = Frame.Conformal3D();

    public static readonly Multivector<double> E2e1 = Multivector<double>.Basis(E2, "e1");
    public static readonly Multivector<double> E3e1 = Multivector<double>.Basis(E3, "e1");
    public static readonly Multivector<double> E3e2 = Multivector<double>.Basis(E3, "e2");
    public static readonly Multivector<double> E3e3 = Multivector<double>.Basis(E3, "e3");
    public static readonly Multivector<double> E3I = Multivector<double>.Basis(E3, "e1^e2^e3");
    public static readonly Multivector<double> CgaNo = Multivector<double>.Basis(Cga, "no");
    public static readonly Multivector<double> CgaNi = Multivector<double>.Basis(Cga, "ni");
    public static readonly Multivector<double> CgaI3 = Multivector<double>.Basis(Cga, "e1^e2^e3");
    public static readonly Multivector<double> CgaIi = -Multivector<double>.Basis(Cga, "no^e1^e2^e3^ni");
    public static readonly Multivector<double> CgaOne = Multivector<double>.FromScalar(Cga, 1.0);
    public static readonly Multivector<double> E3One = Multivector<double>.FromScalar(E3, 1.0);

    public static Multivector<double> Of(Vec2 v) => Multivector<double>.Vector(E2, v.x, v.y);

    public static Multivector<double> Of(Vec3 v) => Multivector<double>.Vector(E3, v.x, v.y, v.z);

    public static Multivector<double> Scalar3(double s) => Multivector<double>.FromScalar(E3, s);

    /// <summary>R = w + x e2e3 + y e3e1 + z e1e2 (7.7).</summary>
    public static Multivector<double> Of(Rotor3 r) =>
        Multivector<double>.FromScalar(E3, r.w)
        + r.x * Multivector<double>.Basis(E3, "e2^e3")
        + r.y * Multivector<double>.Basis(E3, "e3^e1")
        + r.z * Multivector<double>.Basis(E3, "e1^e2");

    /// <summary>A Euclidean vector of the conformal frame.</summary>
    public static Multivector<double> ConformalVector(Vec3 v) => Multivector<double>.Vector(Cga, 0, v.x, v.y, v.z, 0);

    /// <summary>The normalized point no + p + ½p² ni (3.70).</summary>
    public static Multivector<double> Point(Vec3 v) =>
        Multivector<double>.Vector(Cga, 1, v.x, v.y, v.z, (v.x * v.x + v.y * v.y + v.z * v.z) / 2);

    public static Vec2 ToVec2(Multivector<double> m) => new(m["e1"], m["e2"]);

    public static Vec3 ToVec3(Multivector<double> m) => new(m["e1"], m["e2"], m["e3"]);

    public static Rotor3 ToRotor(Multivector<double> m) => new(m.ScalarPart, m["e2^e3"], m["e3^e1"], m["e1^e2"]);
}
