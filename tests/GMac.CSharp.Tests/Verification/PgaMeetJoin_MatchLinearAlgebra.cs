using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// The generated code of the PGA meet and join macros (dsl/macros/pga-meet-join.gmac), compiled and
/// run, against plain linear algebra: cross products, a 3×3 solve, a line-plane parameter. Nothing
/// here goes through GMac's algebra, so a sign or complement convention that is off shows.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class PgaMeetJoin_MatchLinearAlgebra
{
    private const int Samples = 25;

    private static double[] Cross(double[] u, double[] v) =>
        [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];

    private static double Dot(double[] u, double[] v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];

    private static double[] Minus(double[] u, double[] v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];

    private static double[] Point(Random r) => [r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2];

    // x e032 + y e013 + z e021 + w e123 in the canonical blades e023, e013, e012, e123.
    private static void SetPoint(Dictionary<string, double> inputs, string name, double[] p, double w = 1)
    {
        inputs[$"{name}_e0_e2_e3"] = -p[0] * w;
        inputs[$"{name}_e0_e1_e3"] = p[1] * w;
        inputs[$"{name}_e0_e1_e2"] = -p[2] * w;
        inputs[$"{name}_e1_e2_e3"] = w;
    }

    private static double[] GetPoint(Dictionary<string, double> o, string name)
    {
        var w = o[$"{name}_e1_e2_e3"];
        return [-o[$"{name}_e0_e2_e3"] / w, o[$"{name}_e0_e1_e3"] / w, -o[$"{name}_e0_e1_e2"] / w];
    }

    // n1 e1 + n2 e2 + n3 e3 + d e0: the plane n·x + d = 0.
    private static void SetPlane(Dictionary<string, double> inputs, string name, double[] n, double d)
    {
        inputs[$"{name}_e1"] = n[0];
        inputs[$"{name}_e2"] = n[1];
        inputs[$"{name}_e3"] = n[2];
        inputs[$"{name}_e0"] = d;
    }

    private static (double[] Normal, double Offset) RandomPlane(Random r) => (Point(r), r.NextDouble() * 2 - 1);

    private static void Close(double expected, double actual, double scale = 1) =>
        Assert.True(Math.Abs(expected - actual) <= 1e-9 * Math.Max(1, scale), $"expected {expected}, got {actual}");

    [Fact]
    public void Plane_through_three_points_has_normal_b_minus_a_cross_c_minus_a_and_offset_minus_n_dot_a()
    {
        var kernel = MacroKernel.Create("PgaPlaneThroughPoints", "double");
        var r = new Random(11);
        for (var i = 0; i < Samples; i++)
        {
            var (a, b, c) = (Point(r), Point(r), Point(r));
            var w = r.NextDouble() + 0.5; // homogeneous weight of each point: the plane scales by w³
            var inputs = new Dictionary<string, double>();
            SetPoint(inputs, "a", a, w);
            SetPoint(inputs, "b", b, w);
            SetPoint(inputs, "c", c, w);
            var o = kernel.Run(inputs);
            var n = Cross(Minus(b, a), Minus(c, a));
            var w3 = w * w * w;
            Close(n[0] * w3, o["p_e1"], 10);
            Close(n[1] * w3, o["p_e2"], 10);
            Close(n[2] * w3, o["p_e3"], 10);
            Close(-Dot(n, a) * w3, o["p_e0"], 10);
        }
    }

    [Fact]
    public void Line_through_two_points_has_direction_b_minus_a_and_moment_a_cross_b()
    {
        var kernel = MacroKernel.Create("PgaLineThroughPoints", "double");
        var r = new Random(12);
        for (var i = 0; i < Samples; i++)
        {
            var (a, b) = (Point(r), Point(r));
            var inputs = new Dictionary<string, double>();
            SetPoint(inputs, "a", a);
            SetPoint(inputs, "b", b);
            var o = kernel.Run(inputs);
            var (d, m) = (Minus(b, a), Cross(a, b));
            // direction on e23, e31 = −e13, e12; moment on e01, e02, e03
            Close(d[0], o["l_e2_e3"]);
            Close(d[1], -o["l_e1_e3"]);
            Close(d[2], o["l_e1_e2"]);
            Close(m[0], o["l_e0_e1"]);
            Close(m[1], o["l_e0_e2"]);
            Close(m[2], o["l_e0_e3"]);
        }
    }

    [Fact]
    public void Meet_of_two_planes_is_the_line_along_the_cross_product_of_their_normals()
    {
        var kernel = MacroKernel.Create("PgaMeetPlanes", "double");
        var r = new Random(13);
        for (var i = 0; i < Samples; i++)
        {
            var ((n, d), (m, e)) = (RandomPlane(r), RandomPlane(r));
            var inputs = new Dictionary<string, double>();
            SetPlane(inputs, "p", n, d);
            SetPlane(inputs, "q", m, e);
            var o = kernel.Run(inputs);
            var u = Cross(n, m);
            Close(u[0], o["l_e2_e3"]);
            Close(u[1], -o["l_e1_e3"]);
            Close(u[2], o["l_e1_e2"]);
            // The moment is x × u for any point x on both planes: the one nearest the origin solves
            // n·x = −d, m·x = −e, u·x = 0 (Cramer's rule).
            var x = Solve([n, m, u], [-d, -e, 0]);
            var moment = Cross(x, u);
            Close(moment[0], o["l_e0_e1"], 10);
            Close(moment[1], o["l_e0_e2"], 10);
            Close(moment[2], o["l_e0_e3"], 10);
        }
    }

    [Fact]
    public void Meet_of_three_planes_is_the_solution_of_their_three_equations()
    {
        var kernel = MacroKernel.Create("PgaMeetThreePlanes", "double");
        var r = new Random(14);
        for (var i = 0; i < Samples; i++)
        {
            var ((n, d), (m, e), (k, f)) = (RandomPlane(r), RandomPlane(r), RandomPlane(r));
            if (Math.Abs(Det([n, m, k])) < 0.05) continue;
            var inputs = new Dictionary<string, double>();
            SetPlane(inputs, "p", n, d);
            SetPlane(inputs, "q", m, e);
            SetPlane(inputs, "r", k, f);
            var o = kernel.Run(inputs);
            var expected = Solve([n, m, k], [-d, -e, -f]);
            var actual = GetPoint(o, "x");
            for (var j = 0; j < 3; j++) Close(expected[j], actual[j], 1e3);
            // and the weight is the determinant of the normals (the orientation of the meet)
            Close(Det([n, m, k]), o["x_e1_e2_e3"], 10);
        }
    }

    [Fact]
    public void Meet_of_a_line_and_a_plane_is_where_the_parametric_line_crosses_the_plane()
    {
        var lineKernel = MacroKernel.Create("PgaLineThroughPoints", "double");
        var kernel = MacroKernel.Create("PgaMeetLinePlane", "double");
        var r = new Random(15);
        for (var i = 0; i < Samples; i++)
        {
            var (a, b) = (Point(r), Point(r));
            var (n, d) = RandomPlane(r);
            var along = Dot(n, Minus(b, a));
            if (Math.Abs(along) < 0.05) continue;
            var points = new Dictionary<string, double>();
            SetPoint(points, "a", a);
            SetPoint(points, "b", b);
            var line = lineKernel.Run(points);
            var inputs = line.ToDictionary(kv => kv.Key, kv => kv.Value);
            SetPlane(inputs, "p", n, d);
            var o = kernel.Run(inputs);
            var t = -(Dot(n, a) + d) / along;
            var actual = GetPoint(o, "x");
            for (var j = 0; j < 3; j++) Close(a[j] + t * (b[j] - a[j]), actual[j], 1e3);
        }
    }

    private static double Det(double[][] rows) => Dot(rows[0], Cross(rows[1], rows[2]));

    // Cramer's rule on the rows: x = (rhs₀ (r1×r2) + rhs₁ (r2×r0) + rhs₂ (r0×r1)) / det.
    private static double[] Solve(double[][] rows, double[] rhs)
    {
        var det = Det(rows);
        var (c0, c1, c2) = (Cross(rows[1], rows[2]), Cross(rows[2], rows[0]), Cross(rows[0], rows[1]));
        return [.. Enumerable.Range(0, 3).Select(j => (rhs[0] * c0[j] + rhs[1] * c1[j] + rhs[2] * c2[j]) / det)];
    }
}
