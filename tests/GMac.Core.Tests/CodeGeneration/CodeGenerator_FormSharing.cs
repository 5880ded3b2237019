using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Rewrites;
using GMac.Core.Symbolic;
using static GMac.Core.Tests.CodeGeneration.Kernels;

namespace GMac.Core.Tests.CodeGeneration;

public class CodeGenerator_FormSharing
{
    private static CodeGenerationRequest SphereThroughFourPoints() => new(
        r =>
        {
            Multivector<Scalar> Point(string n)
            {
                var pe = Multivector<Scalar>.Vector(Cga, 0, Scalar.Variable($"{n}.x"), Scalar.Variable($"{n}.y"), Scalar.Variable($"{n}.z"), 0);
                return R(r, Multivector<Scalar>.Basis(Cga, "no") + pe + Multivector<Scalar>.Basis(Cga, "ni") * (pe.Sp(pe).ScalarPart / 2));
            }
            var sphere = Multivector<Scalar>.OuterProductOfVectors([Point("p1"), Point("p2"), Point("p3"), Point("p4")], m => R(r, m));
            return Outputs("s", R(r, sphere.Lcp(Multivector<Scalar>.Pseudoscalar(Cga).Inverse())), "no", "e1", "e2", "e3", "ni");
        },
        new[] { "p1", "p2", "p3", "p4" }.SelectMany(p => new[] { "x", "y", "z" }.Select(c => $"{p}.{c}")).ToDictionary(k => k, k => k),
        OutputTargets("s", "no", "e1", "e2", "e3", "ni"));

    /// <summary>(u + v)·(u + v) − (u − v)·(u − v) = 4 u·v: only the expanded form sees the cancellation.</summary>
    private static CodeGenerationRequest DifferenceOfSquares() => new(
        r =>
        {
            var u = SymbolicMultivector.VectorVariables(E3, "u");
            var v = SymbolicMultivector.VectorVariables(E3, "v");
            var (s, d) = (R(r, u + v), R(r, u - v));
            return Outputs("w", R(r, s.Sp(s) - d.Sp(d)), "1");
        },
        VectorInputs(E3, "u", "v"),
        OutputTargets("w", "1"));

    private static CodeGenerationRequest NormalToTwoVectors() => new(
        r =>
        {
            var u = SymbolicMultivector.VectorVariables(E3, "u");
            var v = SymbolicMultivector.VectorVariables(E3, "v");
            return Outputs("w", R(r, R(r, u.Op(v)).Lcp(Multivector<Scalar>.Pseudoscalar(E3).Inverse())), "e1", "e2", "e3");
        },
        VectorInputs(E3, "u", "v"),
        OutputTargets("w", "e1", "e2", "e3"));

    [Fact]
    public void Lowering_with_a_limit_gives_up_exactly_when_the_whole_block_passes_it()
    {
        var request = SphereThroughFourPoints();
        var program = request.Evaluate(null);
        var whole = CodeGenerator.Build(program, [], request);
        var shared = SharedCost.Of(whole);

        var atLimit = CodeGenerator.Build(program, [], request, shared);
        Assert.NotNull(atLimit);
        Assert.True(atLimit.HasSameStatements(whole));
        Assert.Null(CodeGenerator.Build(program, [], request, shared - 1));
        Assert.Null(CodeGenerator.Build(program, [], request, 10));
    }

    [Fact]
    public void Joined_form_that_cancels_is_kept_and_wins()
    {
        var result = CodeGenerator.Generate(DifferenceOfSquares());

        Assert.Equal(JoinMode.Joined, result.Form);
        // 4(u.x v.x + u.y v.y + u.z v.z): three products, two additions, one scaling
        Assert.Equal(6, result.Statistics.Cost);
    }

    [Fact]
    public void Generated_cost_is_the_least_of_the_forms_built_and_optimized_separately()
    {
        foreach (var request in new[] { DifferenceOfSquares(), NormalToTwoVectors() })
        {
            var costs = new List<int>();
            foreach (var statementsOnly in new[] { false, true })
            {
                var recorder = new TemporaryRecorder(null, statementsOnly);
                var program = request.Evaluate(recorder);
                costs.Add(Optimizer.Optimize(CodeGenerator.Build(program, recorder.Temporaries, request)).Statistics().Cost);
            }
            costs.Add(Optimizer.Optimize(CodeGenerator.Build(request.Evaluate(null), [], request)).Statistics().Cost);

            Assert.Equal(costs.Min(), CodeGenerator.Generate(request).Statistics.Cost);
        }
    }

    [Fact]
    public void Equal_built_blocks_are_optimized_once_and_different_ones_apart()
    {
        var request = DifferenceOfSquares();
        var memo = new FormMemo();
        var first = CodeGenerator.Build(request.Evaluate(null), [], request);
        var same = CodeGenerator.Build(request.Evaluate(null), [], request);
        var recorder = new TemporaryRecorder();
        var split = CodeGenerator.Build(request.Evaluate(recorder), recorder.Temporaries, request);
        Assert.NotSame(first, same);

        var optimized = memo.Optimized(first, "first");
        Assert.Same(optimized, memo.Optimized(same, "same"));
        Assert.True(optimized.HasSameStatements(Optimizer.Optimize(same)));
        Assert.False(split.HasSameStatements(first));
        Assert.True(memo.Optimized(split, "split").HasSameStatements(Optimizer.Optimize(split)));
    }

    [Fact]
    public void A_program_is_built_again_unless_its_statements_and_temporaries_are_the_same()
    {
        var request = DifferenceOfSquares();
        var memo = new FormMemo();
        var recorder = new TemporaryRecorder();
        var program = request.Evaluate(recorder);
        var built = CodeGenerator.Build(program, recorder.Temporaries, request);
        memo.Remember(program, recorder.Temporaries, built);

        var again = new TemporaryRecorder();
        Assert.Same(built, memo.BuiltFrom(request.Evaluate(again), again.Temporaries));
        Assert.Null(memo.BuiltFrom(program, []));
        Assert.Null(memo.BuiltFrom(request.Evaluate(null), []));
    }
}
