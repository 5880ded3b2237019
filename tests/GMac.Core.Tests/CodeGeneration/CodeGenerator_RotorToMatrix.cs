using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.Symbolic;
using static GMac.Core.Tests.CodeGeneration.Kernels;

namespace GMac.Core.Tests.CodeGeneration;

public class CodeGenerator_RotorToMatrix
{
    /// <summary>Thesis (7.4)–(7.7): the columns R eᵢ R̃ of the rotation matrix of a unit rotor.</summary>
    private static CodeGenerationRequest Request(bool normalized)
    {
        Scalar V(string n) => Scalar.Variable(n);
        var relations = normalized
            ? SideRelations.None.With(V("w") * V("w") + V("x") * V("x") + V("y") * V("y") + V("z") * V("z"), 1, V("w") * V("w"))
            : SideRelations.None;
        var assumptions = Assumptions.None.WithRelations(relations);
        var cas = new RuleBasedCas();
        var inputs = new[] { "w", "x", "y", "z" }.ToDictionary(k => k, k => $"R.{k}", StringComparer.Ordinal);
        var outputs = new Dictionary<string, string>(StringComparer.Ordinal);
        for (var c = 1; c <= 3; c++)
        for (var r = 1; r <= 3; r++)
            outputs[$"v{c}.e{r}"] = $"m{r}{c}";
        return new CodeGenerationRequest(rec =>
        {
            // R = w + x e23 + y e31 + z e12 (7.7)
            var rotor = Multivector<Scalar>.FromScalar(E3, V("w"))
                + Multivector<Scalar>.Basis(E3, "e2^e3") * V("x")
                + Multivector<Scalar>.Basis(E3, "e3^e1") * V("y")
                + Multivector<Scalar>.Basis(E3, "e1^e2") * V("z");
            var statements = new List<SymbolicStatement>();
            for (var c = 1; c <= 3; c++)
            {
                var column = R(rec, R(rec, rotor.Gp(Multivector<Scalar>.Basis(E3, $"e{c}"))).Gp(rotor.Reverse()));
                for (var r = 1; r <= 3; r++) statements.Add(new SymbolicOutput($"v{c}.e{r}", column[$"e{r}"]));
            }
            return new SymbolicProgram(statements);
        }, inputs, outputs)
        {
            Simplify = s => cas.Simplify(s, assumptions),
        };
    }

    [Fact]
    public void Normalized_rotor_gives_the_reduced_diagonal_7_6()
    {
        var request = Request(normalized: true);
        var simplified = request.Evaluate(null).Statements.OfType<SymbolicOutput>()
            .ToDictionary(o => o.Name, o => request.Simplify!(o.Value));
        Scalar V(string n) => Scalar.Variable(n);
        Scalar Two(Scalar s) => s * 2;
        Assert.Same(1 - Two(V("y") * V("y")) - Two(V("z") * V("z")), simplified["v1.e1"]);
        Assert.Same(1 - Two(V("x") * V("x")) - Two(V("z") * V("z")), simplified["v2.e2"]);
        Assert.Same(1 - Two(V("x") * V("x")) - Two(V("y") * V("y")), simplified["v3.e3"]);
        Assert.Same(Two(V("x") * V("y")) - Two(V("w") * V("z")), simplified["v1.e2"]);

        var result = CodeGenerator.Generate(request);
        var code = BlockText.Of(result.Block);
        // the doubled operands of the hand-written matrix: 1 − (y·2y + z·2z), 15 additions and 9 products
        Assert.Contains("m11 = 1.0 - ", code);
        Assert.DoesNotContain("2.0 *", code);
        Assert.DoesNotContain("R.w * R.w", code);
        Assert.Equal((15, 9), (result.Statistics.Additions, result.Statistics.Multiplications));

        // on unit rotors the code is the rotation matrix of (7.5)
        var random = new Random(70);
        for (var trial = 0; trial < 10; trial++)
        {
            var q = Enumerable.Range(0, 4).Select(_ => random.NextDouble() * 2 - 1).ToArray();
            var n = Math.Sqrt(q.Sum(c => c * c));
            var (w, x, y, z) = (q[0] / n, q[1] / n, q[2] / n, q[3] / n);
            var m = result.Block.Evaluate(new Dictionary<string, double> { ["w"] = w, ["x"] = x, ["y"] = y, ["z"] = z });
            Assert.Equal(w * w + x * x - y * y - z * z, m["v1.e1"], 12);
            Assert.Equal(-2 * w * z + 2 * x * y, m["v1.e2"], 12);
            Assert.Equal(2 * w * y + 2 * x * z, m["v1.e3"], 12);
        }
    }

    [Fact]
    public void Without_the_constraint_the_diagonal_keeps_all_four_squares()
    {
        var code = BlockText.Of(CodeGenerator.Generate(Request(normalized: false)).Block);
        Assert.Contains("R.w * R.w", code);
    }
}
