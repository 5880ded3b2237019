using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.Symbolic;
using static GMac.Core.Tests.CodeGeneration.Kernels;

namespace GMac.Core.Tests.CodeGeneration;

public class CodeGenerator_Twist
{
    /// <summary>Operation counts of the thesis' Figure 6-6 code (counted by hand, each Math call once).</summary>
    internal static readonly CodeStatistics Figure66 = new(Additions: 34, Multiplications: 40, Divisions: 16, Calls: 17, Negations: 0, Temporaries: 24);

    /// <summary>
    /// A full twist applied to a point (Figure 6-6): rotation by cr about the axis through o with
    /// direction a, then translation by ct·a along it, as conformal versors (3.93)–(3.97).
    /// </summary>
    internal static CodeGenerationRequest Request()
    {
        Scalar V(string n) => Scalar.Variable(n);
        Multivector<Scalar> E(Scalar x, Scalar y, Scalar z) => Multivector<Scalar>.Vector(Cga, 0, x, y, z, 0);
        var ni = Multivector<Scalar>.Basis(Cga, "ni");
        var no = Multivector<Scalar>.Basis(Cga, "no");
        var one = Multivector<Scalar>.FromScalar(Cga, 1);
        var half = Scalar.Constant(new GMac.Core.Numerics.Rational(1, 2));
        var i3 = Multivector<Scalar>.Basis(Cga, "e1^e2^e3");
        var assumptions = Assumptions.None.WithRelations(SideRelations.Trigonometric);
        var cas = new RuleBasedCas();

        var inputs = new[] { "a.x", "a.y", "a.z", "o.x", "o.y", "o.z", "p.x", "p.y", "p.z", "cr", "ct" }.ToDictionary(k => k, k => k, StringComparer.Ordinal);
        var outputs = new Dictionary<string, string> { ["q.e1"] = "x", ["q.e2"] = "y", ["q.e3"] = "z" };
        return new CodeGenerationRequest(r =>
        {
            var a = E(V("a.x"), V("a.y"), V("a.z"));
            var o = E(V("o.x"), V("o.y"), V("o.z"));
            var pe = E(V("p.x"), V("p.y"), V("p.z"));
            var p = R(r, no + pe + ni * (pe.Sp(pe).ScalarPart * half));
            var n = R(r, a / a.Norm());
            var rotor = R(r, one * Scalar.Cos(V("cr") * half) - n.Lcp(i3) * Scalar.Sin(V("cr") * half));
            var toOrigin = R(r, one - o.Op(ni) * half);
            var generalRotation = R(r, R(r, toOrigin.Gp(rotor)).Gp(toOrigin.Inverse()));
            var alongAxis = R(r, one - (a * V("ct")).Op(ni) * half);
            var twist = R(r, alongAxis.Gp(generalRotation));
            var q = R(r, R(r, twist.Gp(p)).Gp(R(r, twist.Inverse())));
            return Outputs("q", q, "e1", "e2", "e3");
        }, inputs, outputs)
        {
            Simplify = s => cas.Simplify(s, assumptions),
        };
    }

    [Fact]
    public void Full_twist_needs_fewer_operations_than_figure_66_and_moves_points_correctly()
    {
        var request = Request();
        var result = CodeGenerator.Generate(request);
        var s = result.Statistics;
        Assert.True(s.Cost < Figure66.Cost && s.Operations < Figure66.Operations,
            $"generated {s} (cost {s.Cost}); Figure 6-6 {Figure66} (cost {Figure66.Cost})\n{BlockText.Of(result.Block)}");

        // independent truth: Rodrigues' rotation about the axis through o, then the shift ct·a
        var random = new Random(60);
        for (var trial = 0; trial < 10; trial++)
        {
            var v = request.InputText.Keys.ToDictionary(k => k, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var outputs = result.Block.Evaluate(v);
            double[] axis = [v["a.x"], v["a.y"], v["a.z"]];
            var len = Math.Sqrt(axis.Sum(c => c * c));
            var k = axis.Select(c => c / len).ToArray();
            double[] rel = [v["p.x"] - v["o.x"], v["p.y"] - v["o.y"], v["p.z"] - v["o.z"]];
            var (cos, sin) = (Math.Cos(v["cr"]), Math.Sin(v["cr"]));
            var dot = k[0] * rel[0] + k[1] * rel[1] + k[2] * rel[2];
            double[] cross = [k[1] * rel[2] - k[2] * rel[1], k[2] * rel[0] - k[0] * rel[2], k[0] * rel[1] - k[1] * rel[0]];
            var o = new[] { v["o.x"], v["o.y"], v["o.z"] };
            for (var i = 0; i < 3; i++)
            {
                var expected = o[i] + rel[i] * cos + cross[i] * sin + k[i] * dot * (1 - cos) + v["ct"] * axis[i];
                var actual = outputs[$"q.e{i + 1}"];
                Assert.True(Math.Abs(expected - actual) < 1e-9, $"coordinate {i + 1}: expected {expected}, got {actual}");
            }
        }
    }
}
