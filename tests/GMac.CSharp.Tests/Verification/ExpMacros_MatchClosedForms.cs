using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.Dsl;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// exp in generated, compiled code against closed forms: a 3D rotor at 0, where the squares
/// underflow, near 0 and at large angles; a conformal dilator against scaling of points; a
/// Cl(1,3) boost against the Lorentz matrix; PGA translators and rotors against plain translation
/// and rotation of points.
/// </summary>
public sealed class ExpMacros_MatchClosedForms : IDisposable
{
    private const string Dsl = """
        // Cl(1,3): t timelike.
        define frame sta as
            basis: {t, x, y, z}
            signature (1, 3)
        end frame

        // Projective 3D: e0 null (the last name under signature (3,0,1)).
        define frame pga3 as
            basis: {e1, e2, e3, e0}
            signature (3, 0, 1)
        end frame

        define subspace sta.scalars as basis {1} end subspace
        define subspace sta.vectors as basis {t, x, y, z} end subspace
        define subspace pga3.scalars as basis {1} end subspace
        define subspace pga3.vectors as basis {e1, e2, e3, e0} end subspace
        define subspace pga3.trivectors as basis {e1^e2^e3, e2^e3^e0, e1^e3^e0, e1^e2^e0} end subspace
        define multivector class sta.Scalar as scalars end multivector class
        define multivector class sta.Vector as vectors end multivector class
        define multivector class pga3.Scalar as scalars end multivector class
        define multivector class pga3.Vector as vectors end multivector class
        define multivector class pga3.Point as trivectors end multivector class

        define frame e4 as
            basis: {e1, e2, e3, e4}
            Euclidean
        end frame
        define subspace e4.bivectors as basis {e1^e2, e1^e3, e1^e4, e2^e3, e2^e4, e3^e4} end subspace
        define multivector class e4.Bivector as bivectors end multivector class

        // A rotation in two planes: no blade, so the invariant decomposition.
        define macro ExpBivector4D as
            inputs: { b : e4.Bivector }
            outputs: { r : e4.Multivector }
            performs:
                r = exp(b);
        end macro

        define macro ExpBivector3D as
            inputs: { b : e3d.Bivector }
            outputs: { r : e3d.Rotor }
            performs:
                r = exp(b);
        end macro

        // exp(λ/2 · no∧ni) applied to a point.
        define macro Dilate as
            inputs: { p : cga5d.Vector; lambda : cga5d.Scalar }
            outputs: { q : cga5d.Vector }
            performs:
                q = apply(exp((lambda / 2) * (cga5d.no op cga5d.ni)), p);
        end macro

        // The boost exp(φ/2 · t∧x) applied to a vector.
        define macro Boost as
            inputs: { v : sta.Vector; phi : sta.Scalar }
            outputs: { w : sta.Vector }
            performs:
                w = apply(exp((phi / 2) gp (sta.t op sta.x)), v);
        end macro

        // A PGA translator exp(½ e0∧d) and a rotor exp(−θ/2 e1∧e2) applied to a point trivector.
        define macro PgaMotor as
            inputs: { p : pga3.Point; d : pga3.Vector; theta : pga3.Scalar }
            outputs: { q : pga3.Point }
            performs:
                t = exp(0.5 * (pga3.e0 op d));
                r = exp((-0.5 * theta) gp (pga3.e1 op pga3.e2));
                q = apply(t gp r, p);
        end macro

        // One exp of the rotation plane moved to pass through c: a rotor about the axis through c
        // parallel to e3. Its bivector has e0 parts (a degenerate subspace; square −θ²/4).
        define macro PgaRotationAboutAxis as
            inputs: { p : pga3.Point; c : pga3.Vector; theta : pga3.Scalar }
            outputs: { q : pga3.Point }
            performs:
                tc = exp(0.5 * (pga3.e0 op c));
                q = apply(exp(apply(tc, (-0.5 * theta) gp (pga3.e1 op pga3.e2))), p);
        end macro
        """;

    private readonly TempFolder _folder = new();
    private readonly GenerationContext _context;

    public ExpMacros_MatchClosedForms()
    {
        var file = _folder.Write("exp.gmac", Dsl);
        _context = new GenerationContext(DslProject.Load([SharedDsl.DslDirectory, file]), cacheDirectory: null);
    }

    public void Dispose() => _folder.Dispose();

    private static void Near(double expected, double actual, double tolerance, string what) =>
        Assert.True(double.IsFinite(actual) && Math.Abs(expected - actual) <= tolerance * Math.Max(Math.Abs(expected), 1e-300),
            $"{what}: {actual} instead of {expected}");

    [Theory]
    [InlineData(0.0)]
    [InlineData(1e-200)]
    [InlineData(1e-160)]
    [InlineData(1e-8)]
    [InlineData(0.9)]
    [InlineData(1e4)]
    public void The_generated_rotor_exp_is_finite_and_accurate_at_every_scale(double angle)
    {
        var kernel = MacroKernel.Create("ExpBivector3D", "double", _context);
        // A unit plane (2/3, −1/3, 2/3) scaled by the angle; B = θ·n, exp(B) = cos θ + n sin θ.
        double[] n = [2.0 / 3, -1.0 / 3, 2.0 / 3];
        var r = kernel.Run(new Dictionary<string, double> { ["b_e1_e2"] = angle * n[0], ["b_e1_e3"] = angle * n[1], ["b_e2_e3"] = angle * n[2] });
        var sine = angle == 0 ? 0 : Math.Sin(angle);
        if (angle > 1)
        {
            // The inputs θ·nᵢ are rounded, so the angle they describe is θ within a few ulp(θ):
            // the results can be no closer than that, absolutely.
            var absolute = 8 * Math.BitIncrement(angle) - 8 * angle;
            foreach (var (e, a) in new[] { (Math.Cos(angle), r["r_s"]), (n[0] * sine, r["r_e1_e2"]), (n[1] * sine, r["r_e1_e3"]), (n[2] * sine, r["r_e2_e3"]) })
                Assert.True(Math.Abs(e - a) <= absolute, $"{a} instead of {e}");
            return;
        }
        Near(Math.Cos(angle), r["r_s"], 4e-16, "scalar");
        Near(n[0] * sine, r["r_e1_e2"], 4e-16, "e1^e2");
        Near(n[1] * sine, r["r_e1_e3"], 4e-16, "e1^e3");
        Near(n[2] * sine, r["r_e2_e3"], 4e-16, "e2^e3");
    }

    [Fact]
    public void The_generated_dilator_scales_a_conformal_point_by_e_to_the_lambda()
    {
        var kernel = MacroKernel.Create("Dilate", "double", _context);
        foreach (var lambda in new[] { 0.0, 1e-200, 1e-9, 0.7, -1.3 })
        {
            double[] x = [0.3, -1.2, 2.0];
            var square = x.Sum(c => c * c);
            var q = kernel.Run(new Dictionary<string, double>
            {
                ["p_no"] = 1, ["p_e1"] = x[0], ["p_e2"] = x[1], ["p_e3"] = x[2], ["p_ni"] = square / 2, ["lambda_s"] = lambda,
            });
            // The point of e^λ x, up to its weight (the no coefficient).
            var scale = Math.Exp(lambda);
            Near(scale * x[0], q["q_e1"] / q["q_no"], 1e-14, $"e1 at λ = {lambda}");
            Near(scale * x[1], q["q_e2"] / q["q_no"], 1e-14, $"e2 at λ = {lambda}");
            Near(scale * x[2], q["q_e3"] / q["q_no"], 1e-14, $"e3 at λ = {lambda}");
            Near(scale * scale * square / 2, q["q_ni"] / q["q_no"], 1e-14, $"ni at λ = {lambda}");
        }
    }

    [Fact]
    public void The_generated_boost_is_the_lorentz_matrix()
    {
        var kernel = MacroKernel.Create("Boost", "double", _context);
        foreach (var velocity in new[] { 0.0, 1e-12, 0.3, -0.8, 0.999 })
        {
            var gamma = 1 / Math.Sqrt(1 - velocity * velocity);
            double[] v = [1.5, -0.4, 0.7, 2.0];
            var w = kernel.Run(new Dictionary<string, double>
            {
                ["v_t"] = v[0], ["v_x"] = v[1], ["v_y"] = v[2], ["v_z"] = v[3], ["phi_s"] = Math.Atanh(velocity),
            });
            // Λ = [[γ, −γβ], [−γβ, γ]] on (t, x); y and z unchanged.
            Near(gamma * (v[0] - velocity * v[1]), w["w_t"], 1e-12, $"t at β = {velocity}");
            Near(gamma * (v[1] - velocity * v[0]), w["w_x"], 1e-12, $"x at β = {velocity}");
            Near(v[2], w["w_y"], 1e-15, "y");
            Near(v[3], w["w_z"], 1e-15, "z");
        }
    }

    [Fact]
    public void The_generated_pga_motor_rotates_then_translates_points()
    {
        var kernel = MacroKernel.Create("PgaMotor", "double", _context);
        foreach (var (theta, d) in new[] { (0.0, new[] { 0.0, 0.0, 0.0 }), (0.0, new[] { 1.0, -2.0, 0.5 }), (0.8, new[] { 0.0, 0.0, 0.0 }), (-2.1, new[] { 0.3, 0.4, -1.5 }) })
        {
            double[] x = [0.7, -0.2, 1.1];
            // The point x as a trivector: e1^e2^e3 + x·e2^e3^e0 − y·e1^e3^e0 + z·e1^e2^e0.
            var q = kernel.Run(new Dictionary<string, double>
            {
                ["p_e1_e2_e3"] = 1, ["p_e2_e3_e0"] = x[0], ["p_e1_e3_e0"] = -x[1], ["p_e1_e2_e0"] = x[2],
                ["d_e1"] = d[0], ["d_e2"] = d[1], ["d_e3"] = d[2], ["theta_s"] = theta,
            });
            var w = q["q_e1_e2_e3"];
            double[] moved = [q["q_e2_e3_e0"] / w, -q["q_e1_e3_e0"] / w, q["q_e1_e2_e0"] / w];
            // Rotation by θ about z (counter-clockwise from e1 to e2), then translation by d.
            double[] expected = [Math.Cos(theta) * x[0] - Math.Sin(theta) * x[1] + d[0], Math.Sin(theta) * x[0] + Math.Cos(theta) * x[1] + d[1], x[2] + d[2]];
            for (var i = 0; i < 3; i++) Near(expected[i], moved[i], 1e-13, $"coordinate {i} at θ = {theta}, d = ({string.Join(", ", d)})");
        }
    }

    [Fact]
    public void The_generated_pga_rotor_about_a_shifted_axis_rotates_points_about_that_axis()
    {
        var kernel = MacroKernel.Create("PgaRotationAboutAxis", "double", _context);
        foreach (var theta in new[] { 0.0, 1e-200, 0.5, 3.0 })
        {
            double[] x = [0.7, -0.2, 1.1];
            double[] c = [1.5, -0.5, 0.0];
            var q = kernel.Run(new Dictionary<string, double>
            {
                ["p_e1_e2_e3"] = 1, ["p_e2_e3_e0"] = x[0], ["p_e1_e3_e0"] = -x[1], ["p_e1_e2_e0"] = x[2],
                ["c_e1"] = c[0], ["c_e2"] = c[1], ["c_e3"] = c[2], ["theta_s"] = theta,
            });
            var w = q["q_e1_e2_e3"];
            double[] moved = [q["q_e2_e3_e0"] / w, -q["q_e1_e3_e0"] / w, q["q_e1_e2_e0"] / w];
            var (dx, dy) = (x[0] - c[0], x[1] - c[1]);
            double[] expected = [c[0] + Math.Cos(theta) * dx - Math.Sin(theta) * dy, c[1] + Math.Sin(theta) * dx + Math.Cos(theta) * dy, x[2]];
            for (var i = 0; i < 3; i++) Near(expected[i], moved[i], 1e-13, $"coordinate {i} at θ = {theta}");
        }
    }

    [Theory]
    [InlineData(0.0, 1.0)]
    [InlineData(1e-200, 0.5)]
    [InlineData(1e-8, 1.0)]
    [InlineData(1e-8, 0.3)]
    [InlineData(0.9, 1.0)]
    [InlineData(0.9, 0.4)]
    [InlineData(0.9, 1e-9)]
    [InlineData(50.0, 0.7)]
    public void The_generated_exp_of_a_4d_bivector_is_the_product_of_its_plane_rotations(double angle, double ratio)
    {
        var kernel = MacroKernel.Create("ExpBivector4D", "double", _context);
        // B = θ₁ e1∧u + θ₂ v∧e4 with u = (e2 + e3)/√2, v = (e3 − e2)/√2 orthonormal: two orthogonal
        // planes, θ₁(e12 + e13)/√2 + θ₂(e34 − e24)/√2 in coordinates, and no blade.
        var (t1, t2) = (angle, angle * ratio);
        var h = Math.Sqrt(0.5);
        var r = kernel.Run(new Dictionary<string, double>
        {
            ["b_e1_e2"] = t1 * h, ["b_e1_e3"] = t1 * h, ["b_e3_e4"] = t2 * h, ["b_e2_e4"] = -t2 * h,
        });
        var (c1, s1, c2, s2) = (Math.Cos(t1), Math.Sin(t1), Math.Cos(t2), Math.Sin(t2));
        // (c1 + s1 e1∧u)(c2 + s2 v∧e4) = c1c2 + s1c2 e1∧u + c1s2 v∧e4 + s1s2 e1∧u∧v∧e4, and
        // e1∧u∧v∧e4 = e1∧e2∧e3∧e4 (u∧v = e2∧e3), v∧e4 = (e3∧e4 − e2∧e4)/√2.
        var expected = new Dictionary<string, double>
        {
            ["r_s"] = c1 * c2, ["r_e1_e2"] = s1 * c2 * h, ["r_e1_e3"] = s1 * c2 * h,
            ["r_e3_e4"] = c1 * s2 * h, ["r_e2_e4"] = -c1 * s2 * h, ["r_e1_e2_e3_e4"] = s1 * s2,
        };
        var tolerance = Math.Max(4e-16, 1e-16 * angle * angle);
        foreach (var (name, value) in r)
        {
            Assert.True(double.IsFinite(value), $"{name} is {value}");
            var e = expected.GetValueOrDefault(name);
            Assert.True(Math.Abs(e - value) <= tolerance * Math.Max(1, Math.Abs(angle)), $"{name}: {value} instead of {e}");
            // Near 0 the bivector part is B itself, relatively.
            if (angle is > 0 and < 1e-7 && e != 0 && name.Length == 7)
                Assert.True(Math.Abs(e - value) <= 1e-15 * Math.Abs(e), $"{name}: {value} instead of {e}");
        }
    }
}
