using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.Verification;

/// <summary>
/// The rotor, versor and dual-sphere macros, generated and compiled in double and float, against
/// textbook formulas: Rodrigues' rotation, translation by t, a sphere built from centre and radius.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class RotorAndSphereMacros_MatchFormulas
{
    private static readonly (string Type, double Tolerance)[] Precisions = [("double", 1e-12), ("float", 2e-5)];

    private static double[] Vector(Random random, double scale = 1) => [scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1), scale * (2 * random.NextDouble() - 1)];

    private static double[] UnitVector(Random random)
    {
        var v = Vector(random);
        var n = Math.Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return [v[0] / n, v[1] / n, v[2] / n];
    }

    /// <summary>Rodrigues: x cos θ + (a × x) sin θ + a (a · x)(1 − cos θ), counter-clockwise about the unit axis a.</summary>
    private static double[] Rodrigues(double[] a, double angle, double[] x)
    {
        var (c, s) = (Math.Cos(angle), Math.Sin(angle));
        var dot = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
        double[] cross = [a[1] * x[2] - a[2] * x[1], a[2] * x[0] - a[0] * x[2], a[0] * x[1] - a[1] * x[0]];
        return [.. Enumerable.Range(0, 3).Select(i => x[i] * c + cross[i] * s + a[i] * dot * (1 - c))];
    }

    /// <summary>
    /// R = cos(θ/2) − sin(θ/2) a I₃ with a I₃ = a1 e2^e3 + a2 e3^e1 + a3 e1^e2: the rotor of the
    /// rotation by θ about a, as coefficients of 1, e1^e2, e2^e3, e1^e3 (e3^e1 = −e1^e3), times k.
    /// </summary>
    private static (double S, double E12, double E23, double E13) Rotor(double[] a, double angle, double k)
    {
        var (c, s) = (Math.Cos(angle / 2), Math.Sin(angle / 2));
        return (k * c, -k * s * a[2], -k * s * a[0], k * s * a[1]);
    }

    private static void Near(double[] expected, IReadOnlyList<double> actual, double tolerance)
    {
        for (var i = 0; i < expected.Length; i++)
            Assert.True(Math.Abs(expected[i] - actual[i]) <= tolerance * Math.Max(1, Math.Abs(expected[i])), $"component {i}: {actual[i]} instead of {expected[i]}");
    }

    [Theory]
    [InlineData("ApplyRotor3D")]
    [InlineData("ApplyUnitRotor3D")]
    public void A_rotor_applied_to_a_vector_is_rodrigues_rotation(string macro)
    {
        var random = new Random(3);
        foreach (var (type, tolerance) in Precisions)
        {
            var kernel = MacroKernel.Create(macro, type);
            for (var sample = 0; sample < 20; sample++)
            {
                var (axis, angle, x) = (UnitVector(random), 4 * random.NextDouble() - 2, Vector(random, 3));
                // A general rotor may have any nonzero norm; a unit rotor has norm 1.
                var k = macro == "ApplyRotor3D" ? 0.2 + 3 * random.NextDouble() : 1.0;
                var r = Rotor(axis, angle, k);
                var y = kernel.Run(new Dictionary<string, double>
                {
                    ["r_s"] = r.S, ["r_e1_e2"] = r.E12, ["r_e2_e3"] = r.E23, ["r_e1_e3"] = r.E13,
                    ["x_e1"] = x[0], ["x_e2"] = x[1], ["x_e3"] = x[2],
                });
                Near(Rodrigues(axis, angle, x), [y["y_e1"], y["y_e2"], y["y_e3"]], tolerance * 3);
            }
        }
    }

    [Theory]
    [InlineData("ApplyVersorToPoint")]
    [InlineData("ApplyVersorToPoint3D")]
    public void A_versor_applied_to_a_point_rotates_and_translates_it_at_any_weight(string macro)
    {
        var random = new Random(4);
        foreach (var (type, tolerance) in Precisions)
        {
            var kernel = MacroKernel.Create(macro, type);
            var point = macro == "ApplyVersorToPoint" ? "p" : "x";
            var result = macro == "ApplyVersorToPoint" ? "q" : "y";
            for (var sample = 0; sample < 20; sample++)
            {
                var x = Vector(random, 2);
                var k = (random.Next(2) == 0 ? -1 : 1) * (0.3 + 2 * random.NextDouble());
                var inputs = new Dictionary<string, double> { [$"{point}_e1"] = x[0], [$"{point}_e2"] = x[1], [$"{point}_e3"] = x[2] };
                if (macro == "ApplyVersorToPoint") inputs["p_ni"] = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / 2;
                double[] expected;
                if (sample % 2 == 0)
                {
                    // V = k (1 − ½ t ^ ni) (3.93) moves the point by t.
                    var t = Vector(random, 2);
                    inputs["v_s"] = k;
                    inputs["v_e1_ni"] = -k * t[0] / 2;
                    inputs["v_e2_ni"] = -k * t[1] / 2;
                    inputs["v_e3_ni"] = -k * t[2] / 2;
                    expected = [x[0] + t[0], x[1] + t[1], x[2] + t[2]];
                }
                else
                {
                    var (axis, angle) = (UnitVector(random), 4 * random.NextDouble() - 2);
                    var r = Rotor(axis, angle, k);
                    (inputs["v_s"], inputs["v_e1_e2"], inputs["v_e2_e3"], inputs["v_e1_e3"]) = r;
                    expected = Rodrigues(axis, angle, x);
                }
                var y = kernel.Run(inputs);
                Near(expected, [y[$"{result}_e1"], y[$"{result}_e2"], y[$"{result}_e3"]], tolerance * 10);
                if (macro == "ApplyVersorToPoint")
                {
                    Assert.Equal(1.0, y["q_no"]);
                    Near([(expected[0] * expected[0] + expected[1] * expected[1] + expected[2] * expected[2]) / 2], [y["q_ni"]], tolerance * 10);
                }
            }
        }
    }

    [Fact]
    public void Centre_and_radius_come_back_from_a_dual_sphere_of_any_weight()
    {
        var random = new Random(5);
        foreach (var (type, tolerance) in Precisions)
        {
            var kernel = MacroKernel.Create("SphereCentreAndRadius", type);
            for (var sample = 0; sample < 20; sample++)
            {
                var (c, radius) = (Vector(random, 5), 0.1 + 3 * random.NextDouble());
                var alpha = (random.Next(2) == 0 ? -1 : 1) * (0.2 + 4 * random.NextDouble());
                // ω = α (c − ½ r² ni) with the point c = no + c_E + ½ c_E² ni (3.70, 3.74).
                var c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
                var y = kernel.Run(new Dictionary<string, double>
                {
                    ["omega_no"] = alpha, ["omega_e1"] = alpha * c[0], ["omega_e2"] = alpha * c[1], ["omega_e3"] = alpha * c[2],
                    ["omega_ni"] = alpha * (c2 - radius * radius) / 2,
                });
                // The radius² is a difference of c² and c² − r²: its error grows with c²/r².
                Near(c, [y["centre_e1"], y["centre_e2"], y["centre_e3"]], tolerance);
                Near([radius * radius], [y["squaredRadius_s"]], tolerance * (1 + c2 / (radius * radius)));
                Near([radius], [y["radius_s"]], tolerance * (1 + c2 / (radius * radius)));
            }
            // An imaginary sphere (r² = −1 about the origin): negative squared radius, radius NaN.
            var imaginary = kernel.Run(new Dictionary<string, double> { ["omega_no"] = 1, ["omega_ni"] = 0.5 });
            Assert.Equal(-1.0, imaginary["squaredRadius_s"], tolerance);
            Assert.True(double.IsNaN(imaginary["radius_s"]));
        }
    }
}
