using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// The library's motors between two lines or two planes (dsl/macros/pga-motors.gmac and
/// cga-meet-join.gmac), generated and run, against plain linear algebra: the images of two points
/// lie on the target line or plane, keep their distance, and keep the orientation (direction or
/// normal); and the CGA meets of a line and a plane and of three planes against a line parameter
/// and Cramer's rule.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Motors_MatchLinearAlgebra
{
    private const int Samples = 20;

    private static double[] Cross(double[] u, double[] v) =>
        [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];

    private static double Dot(double[] u, double[] v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];

    private static double[] Minus(double[] u, double[] v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];

    private static double[] Plus(double[] u, double[] v, double s = 1) => [u[0] + s * v[0], u[1] + s * v[1], u[2] + s * v[2]];

    private static double Length(double[] u) => Math.Sqrt(Dot(u, u));

    private static double[] Point(Random r) => [r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2];

    private static void Small(double value, string what) => Assert.True(Math.Abs(value) < 1e-9, $"{what} = {value}");

    // ---- PGA: x e032 + y e013 + z e021 + e123 in the canonical blades e023, e013, e012, e123.
    private static void SetPgaPoint(Dictionary<string, double> inputs, string name, double[] p)
    {
        inputs[$"{name}_e0_e2_e3"] = -p[0];
        inputs[$"{name}_e0_e1_e3"] = p[1];
        inputs[$"{name}_e0_e1_e2"] = -p[2];
        inputs[$"{name}_e1_e2_e3"] = 1;
    }

    private static double[] GetPgaPoint(Dictionary<string, double> o, string name)
    {
        var w = o[$"{name}_e1_e2_e3"];
        return [-o[$"{name}_e0_e2_e3"] / w, o[$"{name}_e0_e1_e3"] / w, -o[$"{name}_e0_e1_e2"] / w];
    }

    // ---- CGA: no + x + ½x² ni, the no coefficient fixed by the class.
    private static void SetCgaPoint(Dictionary<string, double> inputs, string name, double[] p)
    {
        inputs[$"{name}_e1"] = p[0];
        inputs[$"{name}_e2"] = p[1];
        inputs[$"{name}_e3"] = p[2];
        inputs[$"{name}_ni"] = Dot(p, p) / 2;
    }

    private static double[] GetCgaPoint(Dictionary<string, double> o, string name)
    {
        var w = o[$"{name}_no"];
        return [o[$"{name}_e1"] / w, o[$"{name}_e2"] / w, o[$"{name}_e3"] / w];
    }

    /// <summary>Both images on the line through a2 and b2, as far apart as before, in the direction b2 − a2.</summary>
    private static void AssertLineImages(double[] a1, double[] b1, double[] a2, double[] b2, double[] mx, double[] my)
    {
        var d2 = Minus(b2, a2);
        var unit = Plus([0, 0, 0], d2, 1 / Length(d2));
        Small(Length(Cross(Minus(mx, a2), unit)), "distance of the image of a1 from line 2");
        Small(Length(Cross(Minus(my, a2), unit)), "distance of the image of b1 from line 2");
        Small(Length(Minus(my, mx)) - Length(Minus(b1, a1)), "change of distance");
        Assert.True(Dot(Minus(my, mx), d2) > 0, "the motor reverses the line's direction");
    }

    /// <summary>x on plane 1 goes onto plane 2; x + n₁ goes to the image of x plus |n₁| along n₂.</summary>
    private static void AssertPlaneImages(double[] n1, double[] n2, Func<double[], double> plane2, double[] mx, double[] my)
    {
        Small(plane2(mx), "plane 2 at the image of a point of plane 1");
        var expected = Plus(mx, n2, Length(n1) / Length(n2));
        Small(Length(Minus(my, expected)), "image of the normal step");
    }

    [Fact]
    public void Pga_motor_between_lines_moves_line_one_onto_line_two()
    {
        var kernel = MacroKernel.Create("PgaMoveByLines", "double");
        var r = new Random(31);
        for (var i = 0; i < Samples; i++)
        {
            var (a1, b1, a2, b2) = (Point(r), Point(r), Point(r), Point(r));
            var inputs = new Dictionary<string, double>();
            SetPgaPoint(inputs, "a1", a1);
            SetPgaPoint(inputs, "b1", b1);
            SetPgaPoint(inputs, "a2", a2);
            SetPgaPoint(inputs, "b2", b2);
            SetPgaPoint(inputs, "x", a1);
            SetPgaPoint(inputs, "y", b1);
            var o = kernel.Run(inputs);
            AssertLineImages(a1, b1, a2, b2, GetPgaPoint(o, "mx"), GetPgaPoint(o, "my"));
        }
    }

    [Fact]
    public void Pga_motor_between_lines_is_unit_in_both_parts_of_its_study_number()
    {
        // M = s + Σ b e_ij + Σ t e_0i + p e0123 has M M̃ = (s² + |b|²) + 2(s p − (b23 t1 − b13 t2 + b12 t3)) e0123;
        // a unit motor has 1 and 0 there (points alone do not see the second part).
        var kernel = MacroKernel.Create("PgaMotorBetweenLines", "double");
        var r = new Random(37);
        for (var i = 0; i < Samples; i++)
        {
            var inputs = new Dictionary<string, double>();
            foreach (var name in new[] { "k", "l" })
            {
                // a simple line: the moment orthogonal to (b23, −b13, b12), so that b ∧ t = 0
                var (b, t) = (Point(r), Point(r));
                double[] w = [b[2], -b[1], b[0]];
                t = Plus(t, w, -Dot(w, t) / Dot(w, w));
                (inputs[$"{name}_e1_e2"], inputs[$"{name}_e1_e3"], inputs[$"{name}_e2_e3"]) = (b[0], b[1], b[2]);
                (inputs[$"{name}_e0_e1"], inputs[$"{name}_e0_e2"], inputs[$"{name}_e0_e3"]) = (t[0], t[1], t[2]);
            }
            var o = kernel.Run(inputs);
            double Get(string key) => o.TryGetValue(key, out var v) ? v : 0;
            var (sc, p) = (Get("m_s"), Get("m_e0_e1_e2_e3"));
            double b12 = Get("m_e1_e2"), b13 = Get("m_e1_e3"), b23 = Get("m_e2_e3");
            double t1 = Get("m_e0_e1"), t2 = Get("m_e0_e2"), t3 = Get("m_e0_e3");
            Small(sc * sc + b12 * b12 + b13 * b13 + b23 * b23 - 1, "scalar part of M M̃ minus 1");
            Small(sc * p - (b23 * t1 - b13 * t2 + b12 * t3), "pseudoscalar part of M M̃");
        }
    }

    [Fact]
    public void Pga_motor_between_planes_moves_plane_one_onto_plane_two()
    {
        // n·x + d = 0 as n1 e1 + n2 e2 + n3 e3 + d e0.
        var kernel = MacroKernel.Create("PgaMoveByPlanes", "double");
        var r = new Random(32);
        for (var i = 0; i < Samples; i++)
        {
            var (n1, d1, n2, d2) = (Point(r), r.NextDouble() * 2 - 1, Point(r), r.NextDouble() * 2 - 1);
            var inputs = new Dictionary<string, double>
            {
                ["p_e1"] = n1[0], ["p_e2"] = n1[1], ["p_e3"] = n1[2], ["p_e0"] = d1,
                ["q_e1"] = n2[0], ["q_e2"] = n2[1], ["q_e3"] = n2[2], ["q_e0"] = d2,
            };
            var x = Plus([0, 0, 0], n1, -d1 / Dot(n1, n1));
            SetPgaPoint(inputs, "x", x);
            SetPgaPoint(inputs, "y", Plus(x, n1));
            var o = kernel.Run(inputs);
            AssertPlaneImages(n1, n2, p => (Dot(n2, p) + d2) / Length(n2), GetPgaPoint(o, "mx"), GetPgaPoint(o, "my"));
        }
    }

    [Fact]
    public void Cga_motor_between_lines_moves_line_one_onto_line_two()
    {
        var kernel = MacroKernel.Create("CgaMoveByLines", "double");
        var r = new Random(33);
        for (var i = 0; i < Samples; i++)
        {
            var (a1, b1, a2, b2) = (Point(r), Point(r), Point(r), Point(r));
            var inputs = new Dictionary<string, double>();
            SetCgaPoint(inputs, "a1", a1);
            SetCgaPoint(inputs, "b1", b1);
            SetCgaPoint(inputs, "a2", a2);
            SetCgaPoint(inputs, "b2", b2);
            SetCgaPoint(inputs, "x", a1);
            SetCgaPoint(inputs, "y", b1);
            var o = kernel.Run(inputs);
            AssertLineImages(a1, b1, a2, b2, GetCgaPoint(o, "mx"), GetCgaPoint(o, "my"));
        }
    }

    [Fact]
    public void Cga_motor_between_planes_moves_plane_one_onto_plane_two()
    {
        // The dual plane n + δ ni is the plane x·n = δ.
        var kernel = MacroKernel.Create("CgaMoveByPlanes", "double");
        var r = new Random(34);
        for (var i = 0; i < Samples; i++)
        {
            var (n1, d1, n2, d2) = (Point(r), r.NextDouble() * 2 - 1, Point(r), r.NextDouble() * 2 - 1);
            var inputs = new Dictionary<string, double>
            {
                ["p_e1"] = n1[0], ["p_e2"] = n1[1], ["p_e3"] = n1[2], ["p_ni"] = d1,
                ["q_e1"] = n2[0], ["q_e2"] = n2[1], ["q_e3"] = n2[2], ["q_ni"] = d2,
            };
            var x = Plus([0, 0, 0], n1, d1 / Dot(n1, n1));
            SetCgaPoint(inputs, "x", x);
            SetCgaPoint(inputs, "y", Plus(x, n1));
            var o = kernel.Run(inputs);
            AssertPlaneImages(n1, n2, p => (Dot(n2, p) - d2) / Length(n2), GetCgaPoint(o, "mx"), GetCgaPoint(o, "my"));
        }
    }

    [Fact]
    public void Cga_meet_of_a_line_and_a_plane_is_the_point_at_the_line_parameter()
    {
        var kernel = MacroKernel.Create("CgaMeetLinePlane", "double");
        var r = new Random(35);
        for (var i = 0; i < Samples; i++)
        {
            var (a, b, n, d) = (Point(r), Point(r), Point(r), r.NextDouble() * 2 - 1);
            var inputs = new Dictionary<string, double> { ["p_e1"] = n[0], ["p_e2"] = n[1], ["p_e3"] = n[2], ["p_ni"] = d };
            SetCgaPoint(inputs, "a", a);
            SetCgaPoint(inputs, "b", b);
            var o = kernel.Run(inputs);
            var t = (d - Dot(n, a)) / Dot(n, Minus(b, a));
            var x = Plus(a, Minus(b, a), t);
            Small(Length(Minus(x, [o["x_e1"], o["x_e2"], o["x_e3"]])) / Math.Max(1, Length(x)), "distance from the line-plane point");
        }
    }

    [Fact]
    public void Cga_meet_of_three_planes_solves_the_three_plane_equations()
    {
        var kernel = MacroKernel.Create("CgaMeetThreePlanes", "double");
        var r = new Random(36);
        for (var i = 0; i < Samples; i++)
        {
            double[][] n = [Point(r), Point(r), Point(r)];
            double[] d = [r.NextDouble() * 2 - 1, r.NextDouble() * 2 - 1, r.NextDouble() * 2 - 1];
            var inputs = new Dictionary<string, double>();
            foreach (var (name, k) in new[] { ("p", 0), ("q", 1), ("r", 2) })
            {
                inputs[$"{name}_e1"] = n[k][0];
                inputs[$"{name}_e2"] = n[k][1];
                inputs[$"{name}_e3"] = n[k][2];
                inputs[$"{name}_ni"] = d[k];
            }
            var o = kernel.Run(inputs);
            // Cramer's rule for the rows nₖ·x = dₖ: x = (d₀ n₁×n₂ + d₁ n₂×n₀ + d₂ n₀×n₁) / det.
            var det = Dot(n[0], Cross(n[1], n[2]));
            var x = Plus(Plus(Plus([0, 0, 0], Cross(n[1], n[2]), d[0] / det), Cross(n[2], n[0]), d[1] / det), Cross(n[0], n[1]), d[2] / det);
            Small(Length(Minus(x, [o["x_e1"], o["x_e2"], o["x_e3"]])) / Math.Max(1, Length(x)), "distance from the solution");
        }
    }
}
