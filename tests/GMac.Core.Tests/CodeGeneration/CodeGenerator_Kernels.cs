using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.Symbolic;
using static GMac.Core.Tests.CodeGeneration.Kernels;

namespace GMac.Core.Tests.CodeGeneration;

public class CodeGenerator_Kernels
{
    private static readonly string[] E3Vector = ["e1", "e2", "e3"];

    [Fact]
    public void Normal_to_two_vectors_three_assignments_six_products_three_subtractions()
    {
        var request = new CodeGenerationRequest(
            r =>
            {
                var u = SymbolicMultivector.VectorVariables(E3, "u");
                var v = SymbolicMultivector.VectorVariables(E3, "v");
                var t1 = R(r, u.Op(v));
                var w = R(r, t1.Lcp(Multivector<Scalar>.Pseudoscalar(E3).Inverse()));
                return Outputs("w", w, E3Vector);
            },
            VectorInputs(E3, "u", "v"),
            OutputTargets("w", E3Vector));
        var result = CodeGenerator.Generate(request);
        var s = result.Statistics;
        Assert.Equal((6, 3, 0, 0), (s.Multiplications, s.Additions, s.Divisions, s.Temporaries));
        Assert.Equal(3, result.Block.Statements.Count);
        var code = BlockText.Of(result.Block);
        Assert.Equal(
            "w_e1 = u.y * v.z - u.z * v.y;\n" +
            "w_e2 = u.z * v.x - u.x * v.z;\n" +
            "w_e3 = u.x * v.y - u.y * v.x;\n", code);
    }

    [Fact]
    public void Hidden_surface_at_most_two_products_and_five_subtractions()
    {
        // thesis (4.14): the e1^e2 coefficient of (v3 − v1) ∧ (v2 − v1)
        var request = new CodeGenerationRequest(
            r =>
            {
                var v1 = SymbolicMultivector.VectorVariables(E2, "v1");
                var v2 = SymbolicMultivector.VectorVariables(E2, "v2");
                var v3 = SymbolicMultivector.VectorVariables(E2, "v3");
                var b = R(r, R(r, v3 - v1).Op(R(r, v2 - v1)));
                return Outputs("B", b, "e1^e2");
            },
            VectorInputs(E2, "v1", "v2", "v3"),
            OutputTargets("B", "e1^e2"));
        var result = CodeGenerator.Generate(request);
        Assert.True(result.Statistics.Multiplications <= 2, result.Statistics.ToString());
        Assert.True(result.Statistics.Additions <= 5, result.Statistics.ToString());
        AssertAgreesWithNumeric(result.Block, request, 40);
    }

    [Fact]
    public void Sphere_through_four_points_at_most_one_hundred_operations()
    {
        var request = new CodeGenerationRequest(
            r =>
            {
                Multivector<Scalar> Point(string n)
                {
                    var pe = Multivector<Scalar>.Vector(Cga, 0, Scalar.Variable($"{n}.x"), Scalar.Variable($"{n}.y"), Scalar.Variable($"{n}.z"), 0);
                    return R(r, Multivector<Scalar>.Basis(Cga, "no") + pe + Multivector<Scalar>.Basis(Cga, "ni") * (pe.Sp(pe).ScalarPart / 2));
                }
                var (p1, p2, p3, p4) = (Point("p1"), Point("p2"), Point("p3"), Point("p4"));
                var sphere = Multivector<Scalar>.OuterProductOfVectors([p1, p2, p3, p4], m => R(r, m));
                var dual = R(r, sphere.Lcp(Multivector<Scalar>.Pseudoscalar(Cga).Inverse()));
                return Outputs("s", dual, "no", "e1", "e2", "e3", "ni");
            },
            new[] { "p1", "p2", "p3", "p4" }.SelectMany(p => new[] { "x", "y", "z" }.Select(c => $"{p}.{c}")).ToDictionary(k => k, k => k),
            OutputTargets("s", "no", "e1", "e2", "e3", "ni"));
        var result = CodeGenerator.Generate(request);
        Assert.True(result.Statistics.Operations <= 100, $"{result.Form}: {result.Statistics}; other form: {result.Alternative}\n{BlockText.Of(result.Block)}");
        AssertAgreesWithNumeric(result.Block, request, 41);
    }

    /// <summary>The block, run on random inputs, gives the same outputs as the symbolic evaluation.</summary>
    internal static void AssertAgreesWithNumeric(CodeBlock block, CodeGenerationRequest request, int seed)
    {
        var program = request.Evaluate(null);
        var random = new Random(seed);
        for (var trial = 0; trial < 10; trial++)
        {
            var values = request.InputText.Keys.ToDictionary(k => k, _ => random.NextDouble() * 4 - 2, StringComparer.Ordinal);
            var outputs = block.Evaluate(values);
            foreach (var o in program.Statements.OfType<SymbolicOutput>().Where(o => request.OutputTargets.ContainsKey(o.Name)))
            {
                var expected = o.Value.Evaluate(values);
                var actual = outputs.TryGetValue(o.Name, out var a) ? a : 0.0;
                Assert.True(Math.Abs(expected - actual) <= 1e-9 * Math.Max(1, Math.Abs(expected)), $"{o.Name}: expected {expected}, got {actual}\n{block}");
            }
        }
    }
}
