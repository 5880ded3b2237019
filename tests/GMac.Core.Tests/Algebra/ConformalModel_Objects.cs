using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

/// <summary>The conformal model of thesis §3.6–3.9 checked against plain Euclidean geometry.</summary>
public class ConformalModel_Objects
{
    private static readonly Frame C = TestFrames.Conformal;
    private static readonly Multivector<double> No = Multivector<double>.Basis(C, "no");
    private static readonly Multivector<double> Ni = Multivector<double>.Basis(C, "ni");
    private static readonly Multivector<double> I = Multivector<double>.Pseudoscalar(C);
    private static readonly Multivector<double> I3 = Multivector<double>.Basis(C, "e1^e2^e3");

    private static Multivector<double> Euclid(double x, double y, double z) => Multivector<double>.Vector(C, 0, x, y, z, 0);

    /// <summary>(3.70) p = no + p_E + ½ p_E² ni.</summary>
    private static Multivector<double> Point(double x, double y, double z) =>
        No + Euclid(x, y, z) + Ni * (0.5 * (x * x + y * y + z * z));

    private static (double X, double Y, double Z) Coordinates(Multivector<double> p)
    {
        var w = -p.Lcp(Ni).ScalarPart; // normalization weight, 1 for a normalized point
        return (p["e1"] / w, p["e2"] / w, p["e3"] / w);
    }

    private static double[] RandomPoint(Random r) => [r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2];

    [Fact]
    public void Normalized_point_is_null_and_meets_infinity_at_minus_one()
    {
        var r = new Random(20);
        for (var i = 0; i < 20; i++)
        {
            var q = RandomPoint(r);
            var p = Point(q[0], q[1], q[2]);
            Assert.True(p.Gp(p).Terms.All(t => Math.Abs(t.Coefficient) < 1e-12), $"p² = {p.Gp(p)}");
            MultivectorAssert.Close(-1, p.Lcp(Ni).ScalarPart);
        }
    }

    [Fact]
    public void Contraction_of_points_gives_squared_distance()
    {
        var r = new Random(21);
        for (var i = 0; i < 20; i++)
        {
            var (a, b) = (RandomPoint(r), RandomPoint(r));
            var d2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
            MultivectorAssert.Close(d2, -2 * Point(a[0], a[1], a[2]).Lcp(Point(b[0], b[1], b[2])).ScalarPart);
        }
    }

    [Fact]
    public void Sphere_through_four_points_has_the_right_centre_and_radius()
    {
        var r = new Random(22);
        for (var i = 0; i < 20; i++)
        {
            var centre = RandomPoint(r);
            var radius = 0.5 + r.NextDouble() * 2;
            var pts = Enumerable.Range(0, 4).Select(_ =>
            {
                var d = RandomPoint(r);
                var n = Math.Sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                return Point(centre[0] + radius * d[0] / n, centre[1] + radius * d[1] / n, centre[2] + radius * d[2] / n);
            }).ToArray();
            // (3.76): ω = (p1 ∧ p2 ∧ p3 ∧ p4) ⌋ I⁻¹, a dual sphere c − ½ r² ni up to scale
            var omega = pts[0].Op(pts[1]).Op(pts[2]).Op(pts[3]).Lcp(I.Inverse());
            omega /= -omega.Lcp(Ni).ScalarPart;
            var (x, y, z) = Coordinates(omega);
            MultivectorAssert.Close(centre[0], x, 1e-7);
            MultivectorAssert.Close(centre[1], y, 1e-7);
            MultivectorAssert.Close(centre[2], z, 1e-7);
            MultivectorAssert.Close(radius * radius, omega.Gp(omega).ScalarPart, 1e-7); // ω² = r² for a normalized dual sphere
        }
    }

    [Fact]
    public void Plane_through_three_points_has_the_right_normal_and_distance()
    {
        var r = new Random(23);
        for (var i = 0; i < 20; i++)
        {
            var (a, b, c) = (RandomPoint(r), RandomPoint(r), RandomPoint(r));
            // (3.80): Θ = (p1 ∧ p2 ∧ p3 ∧ ni) ⌋ I⁻¹ = n + δ ni up to scale
            var theta = Point(a[0], a[1], a[2]).Op(Point(b[0], b[1], b[2])).Op(Point(c[0], c[1], c[2])).Op(Ni).Lcp(I.Inverse());
            double[] u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            double[] v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            double[] n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
            var len = Math.Sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            var scale = Math.Sqrt(theta["e1"] * theta["e1"] + theta["e2"] * theta["e2"] + theta["e3"] * theta["e3"]);
            var sign = Math.Sign(theta["e1"] * n[0] + theta["e2"] * n[1] + theta["e3"] * n[2]);
            for (var k = 0; k < 3; k++) MultivectorAssert.Close(n[k] / len, sign * theta[$"e{k + 1}"] / scale, 1e-8);
            var delta = (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / len;
            MultivectorAssert.Close(delta, sign * theta["ni"] / scale, 1e-8);
            Assert.True(Math.Abs(theta["no"]) < 1e-9);
        }
    }

    [Fact]
    public void Translator_moves_points()
    {
        var t = Euclid(0.5, -1.5, 2);
        var vt = Multivector<double>.FromScalar(C, 1) - t.Op(Ni) * 0.5; // (3.93)
        var moved = vt.Apply(Point(1, 2, 3));
        MultivectorAssert.Close(Point(1.5, 0.5, 5), moved, 1e-12);
    }

    /// <summary>Rodrigues' formula, the independent truth for rotations.</summary>
    private static double[] Rotate(double[] p, double[] axis, double angle)
    {
        var n = Math.Sqrt(axis.Sum(a => a * a));
        var k = axis.Select(a => a / n).ToArray();
        var dot = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
        double[] cross = [k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0]];
        return Enumerable.Range(0, 3).Select(i => p[i] * Math.Cos(angle) + cross[i] * Math.Sin(angle) + k[i] * dot * (1 - Math.Cos(angle))).ToArray();
    }

    private static Multivector<double> Rotor(double[] axis, double angle)
    {
        // (3.94): R_E = r_E ⌋ I3 is the rotation plane; V = cos(φ/2) − sin(φ/2) R_E/‖R_E‖
        var re = Euclid(axis[0], axis[1], axis[2]).Lcp(I3);
        return Multivector<double>.FromScalar(C, Math.Cos(angle / 2)) - re * (Math.Sin(angle / 2) / re.Norm());
    }

    private static Multivector<double> Translator(double[] t) =>
        Multivector<double>.FromScalar(C, 1) - Euclid(t[0], t[1], t[2]).Op(Ni) * 0.5;

    private static void AssertPoint(double[] expected, Multivector<double> actual)
    {
        var (x, y, z) = Coordinates(actual);
        MultivectorAssert.Close(expected[0], x, 1e-9);
        MultivectorAssert.Close(expected[1], y, 1e-9);
        MultivectorAssert.Close(expected[2], z, 1e-9);
        Assert.True(Math.Abs(actual.Gp(actual).ScalarPart) < 1e-9, "the image is still a point (null vector)");
    }

    [Fact]
    public void Rotor_rotates_about_its_axis_through_the_origin()
    {
        var r = new Random(24);
        for (var i = 0; i < 10; i++)
        {
            var (p, axis, angle) = (RandomPoint(r), RandomPoint(r), r.NextDouble() * 6 - 3);
            AssertPoint(Rotate(p, axis, angle), Rotor(axis, angle).Apply(Point(p[0], p[1], p[2])));
        }
    }

    [Fact]
    public void General_rotation_and_twist_move_about_an_axis_through_a_point()
    {
        var r = new Random(25);
        for (var i = 0; i < 10; i++)
        {
            var (p, axis, through, angle, pitch) = (RandomPoint(r), RandomPoint(r), RandomPoint(r), r.NextDouble() * 6 - 3, r.NextDouble() * 2 - 1);
            var vp = Translator(through);
            var vGr = vp.Gp(Rotor(axis, angle)).Gp(vp.Inverse()); // (3.96)
            var local = Rotate([p[0] - through[0], p[1] - through[1], p[2] - through[2]], axis, angle);
            var rotated = new[] { local[0] + through[0], local[1] + through[1], local[2] + through[2] };
            AssertPoint(rotated, vGr.Apply(Point(p[0], p[1], p[2])));

            var n = Math.Sqrt(axis.Sum(a => a * a));
            var shift = axis.Select(a => a / n * pitch).ToArray();
            var vTw = Translator(shift).Gp(vGr); // (3.97)
            AssertPoint([rotated[0] + shift[0], rotated[1] + shift[1], rotated[2] + shift[2]], vTw.Apply(Point(p[0], p[1], p[2])));
        }
    }

    [Fact]
    public void Reflections_and_scaling_act_as_stated()
    {
        var p = new[] { 0.3, -1.2, 2.5 };
        var pt = Point(p[0], p[1], p[2]);
        // reflection in the plane through the origin with normal n_E
        var n = new[] { 1.0, 2.0, -2.0 };
        var nn = n.Sum(a => a * a);
        var dot = p[0] * n[0] + p[1] * n[1] + p[2] * n[2];
        AssertPoint(Enumerable.Range(0, 3).Select(i => p[i] - 2 * dot / nn * n[i]).ToArray(), Euclid(n[0], n[1], n[2]).Apply(pt));
        // reflection in the origin: V_o = no ∧ ni
        AssertPoint(p.Select(a => -a).ToArray(), No.Op(Ni).Apply(pt));
        // uniform scaling by s: V_s = cosh γ + sinh γ no ∧ ni, γ = ½ ln s
        var s = 2.5;
        var gamma = 0.5 * Math.Log(s);
        var vs = Multivector<double>.FromScalar(C, Math.Cosh(gamma)) + No.Op(Ni) * Math.Sinh(gamma);
        AssertPoint(p.Select(a => s * a).ToArray(), vs.Apply(pt));
        // general reflection in a point q: V_q V_o V_q⁻¹
        var q = new[] { 1.0, 1.0, -1.0 };
        var vq = Translator(q);
        AssertPoint(Enumerable.Range(0, 3).Select(i => 2 * q[i] - p[i]).ToArray(), vq.Gp(No.Op(Ni)).Gp(vq.Inverse()).Apply(pt));
    }

    [Fact]
    public void Direction_vectors_are_translation_invariant()
    {
        var v = Euclid(1, -2, 0.5).Op(Ni); // (3.87)
        var moved = Translator([3, 1, -4]).Apply(v);
        MultivectorAssert.Close(v, moved, 1e-12);
    }
}
