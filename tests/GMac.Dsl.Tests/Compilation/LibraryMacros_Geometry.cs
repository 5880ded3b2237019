using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Compilation;

/// <summary>Library macros against closed-form geometry (Rodrigues, barycentric identities, rotor endpoints).</summary>
public sealed class LibraryMacros_Geometry
{
    private static readonly Lazy<DslProject> Library = new(() => DslProject.Load(RepositoryPaths.DslLibrary));

    private static Dictionary<string, Multivector<double>> Run(string macro, Dictionary<string, double> values)
    {
        var outputs = SymbolicMacro.Compile(Library.Value.Model.Macros[macro]);
        return outputs.ToDictionary(o => o.Key.Name, o => o.Value.Evaluate(values));
    }

    private static void Vector(Dictionary<string, double> values, string name, double[] v, string scalar = "e")
    {
        for (var i = 0; i < v.Length; i++) values[$"{name}.{scalar}{i + 1}"] = v[i];
    }

    [Fact]
    public void Full_twist_rotates_about_the_axis_then_slides_along_it()
    {
        double[] axis = [0.3, -0.5, 0.8], origin = [1, 2, -0.5], p = [-0.7, 0.4, 1.1];
        var (angle, slide) = (0.9, 0.35);
        var values = new Dictionary<string, double> { ["angle.scalar"] = angle, ["tr_param.scalar"] = slide };
        Vector(values, "rot_axis", axis);
        Vector(values, "tr_origin", origin);
        Vector(values, "in_mv", p);
        var result = Run("ApplyTwistToPoint3D", values)["out_mv"];

        // Rodrigues' formula about the unit axis through the origin point, then + slide·axis.
        var len = Math.Sqrt(axis.Sum(a => a * a));
        var k = axis.Select(a => a / len).ToArray();
        var v = p.Zip(origin, (a, b) => a - b).ToArray();
        double[] cross = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]];
        var dot = k.Zip(v, (a, b) => a * b).Sum();
        var (cos, sin) = (Math.Cos(angle), Math.Sin(angle));
        var sign = RotationSense(values);
        for (var i = 0; i < 3; i++)
        {
            var rotated = v[i] * cos + sign * cross[i] * sin + k[i] * dot * (1 - cos);
            Assert.Equal(origin[i] + rotated + slide * axis[i], result[$"e{i + 1}"], 9);
        }
    }

    // The sense of (3.94) with R_E = r ⌋ I3: found once on e1 about e3 instead of assumed.
    private static double RotationSense(Dictionary<string, double> _)
    {
        var values = new Dictionary<string, double> { ["angle.scalar"] = Math.PI / 2, ["tr_param.scalar"] = 0 };
        Vector(values, "rot_axis", [0, 0, 1]);
        Vector(values, "tr_origin", [0, 0, 0]);
        Vector(values, "in_mv", [1, 0, 0]);
        var y = Run("ApplyTwistToPoint3D", values)["out_mv"]["e2"];
        Assert.Equal(1, Math.Abs(y), 9); // a quarter turn either way
        return Math.Sign(y);
    }

    [Fact]
    public void Plucker_barycentrics_sum_to_one_and_rebuild_the_hit_point()
    {
        double[] v1 = [0, 0, 0], v2 = [2, 0, 0.5], v3 = [0.3, 1.5, 0], pr = [0.5, 0.4, 3], vr = [0.1, 0.05, -1];
        var values = new Dictionary<string, double>();
        Vector(values, "v1", v1); Vector(values, "v2", v2); Vector(values, "v3", v3);
        Vector(values, "pr", pr); Vector(values, "vr", vr);
        var o = Run("PluckerRayTriangle", values);
        var (a1, a2, a3, t) = (o["a1"].ScalarPart, o["a2"].ScalarPart, o["a3"].ScalarPart, o["t"].ScalarPart);
        Assert.Equal(1, a1 + a2 + a3, 12);
        // Hit point from the ray parameter equals the barycentric combination (d_i weights edge l_{i}
        // opposite to vertex i+2, so α1 weights v3, α2 weights v1, α3 weights v2).
        for (var i = 0; i < 3; i++)
            Assert.Equal(pr[i] + t * vr[i], a2 * v1[i] + a3 * v2[i] + a1 * v3[i], 9);
    }

    [Fact]
    public void Rotor_to_matrix_columns_are_orthonormal_and_right_handed()
    {
        var (w, x, y, z) = (0.4, -0.3, 0.7, 0.2);
        var n = Math.Sqrt(w * w + x * x + y * y + z * z);
        var values = new Dictionary<string, double>
        {
            ["r.scalar"] = w / n, ["r.e2_e3"] = x / n, ["r.e1_e3"] = -y / n, ["r.e1_e2"] = z / n,
        };
        var o = Run("RotorToMatrix", values);
        var cols = new[] { "c1", "c2", "c3" }.Select(c => new[] { o[c]["e1"], o[c]["e2"], o[c]["e3"] }).ToArray();
        for (var i = 0; i < 3; i++)
        for (var j = 0; j < 3; j++)
            Assert.Equal(i == j ? 1 : 0, cols[i].Zip(cols[j], (a, b) => a * b).Sum(), 12);
        var det = cols[0][0] * (cols[1][1] * cols[2][2] - cols[1][2] * cols[2][1])
                - cols[1][0] * (cols[0][1] * cols[2][2] - cols[0][2] * cols[2][1])
                + cols[2][0] * (cols[0][1] * cols[1][2] - cols[0][2] * cols[1][1]);
        Assert.Equal(1, det, 12);
    }

    // (7.10) divides by φ, so the start is probed just after α = 0.
    [Theory]
    [InlineData(1e-9)]
    [InlineData(1.0)]
    public void Rotor_interpolation_starts_at_r1_and_ends_at_r2(double alpha)
    {
        // R = cos θ + sin θ B̂ with unit bivectors in two different planes.
        var values = new Dictionary<string, double>
        {
            ["r1.scalar"] = Math.Cos(0.4), ["r1.e1_e2"] = Math.Sin(0.4), ["r1.e2_e3"] = 0, ["r1.e1_e3"] = 0,
            ["r2.scalar"] = Math.Cos(0.7), ["r2.e1_e2"] = 0.6 * Math.Sin(0.7), ["r2.e2_e3"] = 0.8 * Math.Sin(0.7), ["r2.e1_e3"] = 0,
            ["alpha.scalar"] = alpha,
        };
        var r = Run("RotorInterpolate", values)["r"];
        var prefix = alpha < 0.5 ? "r1" : "r2";
        Assert.Equal(values[$"{prefix}.scalar"], r.ScalarPart, 7);
        Assert.Equal(values[$"{prefix}.e1_e2"], r["e1^e2"], 7);
        Assert.Equal(values[$"{prefix}.e2_e3"], r["e2^e3"], 7);
    }

    [Theory]
    [InlineData(0.5)]
    [InlineData(1.0)]
    public void Rotor_interpolation_follows_slerp_when_the_relative_rotor_has_a_negative_scalar_part(double alpha)
    {
        // R1·R2 = cos 0.3 cos 2.2 + sin 0.3 sin 2.2 · 0.6 < 0: the relative rotor turns by more than π/2.
        double[] r1 = [Math.Cos(0.3), Math.Sin(0.3), 0, 0];
        double[] r2 = [Math.Cos(2.2), 0.6 * Math.Sin(2.2), 0.8 * Math.Sin(2.2), 0];
        var values = new Dictionary<string, double>
        {
            ["r1.scalar"] = r1[0], ["r1.e1_e2"] = r1[1], ["r1.e2_e3"] = r1[2], ["r1.e1_e3"] = r1[3],
            ["r2.scalar"] = r2[0], ["r2.e1_e2"] = r2[1], ["r2.e2_e3"] = r2[2], ["r2.e1_e3"] = r2[3],
            ["alpha.scalar"] = alpha,
        };
        var dot = r1.Zip(r2, (a, b) => a * b).Sum();
        Assert.True(dot < 0);
        var omega = Math.Acos(dot);
        var w1 = Math.Sin((1 - alpha) * omega) / Math.Sin(omega);
        var w2 = Math.Sin(alpha * omega) / Math.Sin(omega);
        var r = Run("RotorInterpolate", values)["r"];
        Assert.Equal(w1 * r1[0] + w2 * r2[0], r.ScalarPart, 9);
        Assert.Equal(w1 * r1[1] + w2 * r2[1], r["e1^e2"], 9);
        Assert.Equal(w1 * r1[2] + w2 * r2[2], r["e2^e3"], 9);
        Assert.Equal(w1 * r1[3] + w2 * r2[3], r["e1^e3"], 9);
    }

    [Fact]
    public void Sphere_through_four_points_has_their_center_and_radius()
    {
        double[] c = [0.5, -1, 2];
        var rad = 1.7;
        double[][] dirs = [[1, 0, 0], [0, 1, 0], [0, 0, -1], [0.6, 0, 0.8]];
        var values = new Dictionary<string, double>();
        for (var k = 0; k < 4; k++)
        {
            var p = dirs[k].Select((d, i) => c[i] + rad * d).ToArray();
            Vector(values, $"p{k + 1}", p);
            values[$"p{k + 1}.ni"] = p.Sum(a => a * a) / 2;
        }
        var omega = Run("SphereThroughPoints", values)["omega"];
        // ω ∝ c − ½ r² ni with the no coefficient as scale (3.74).
        var s = omega["no"];
        for (var i = 0; i < 3; i++) Assert.Equal(c[i], omega[$"e{i + 1}"] / s, 9);
        Assert.Equal((c.Sum(a => a * a) - rad * rad) / 2, omega["ni"] / s, 9);
    }
}
