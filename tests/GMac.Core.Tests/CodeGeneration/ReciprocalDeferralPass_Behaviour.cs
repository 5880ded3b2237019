using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using GMac.Core.Symbolic;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.Kernels;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class ReciprocalDeferralPass_Behaviour
{
    private static readonly Expr R = Variable("r"), T1 = Variable("t1"), T2 = Variable("t2"), T3 = Variable("t3");

    /// <summary>r = 1/(a² + b²), three scaled temporaries t = −x·r, then two outputs that mix them linearly.</summary>
    private static CodeBlock ScaledThenMixed() => Block(
        Temp("r", Quotient(ConstantExpr.One, Sum(Product(A, A), Product(B, B)))),
        Temp("t1", Negate(Product(A, R))),
        Temp("t2", Negate(Product(B, R))),
        Temp("t3", Negate(Product(C, R))),
        Out("o1", Sum(Product(D, T1), Negate(Product(A, T2)), Product(B, T3))),
        Out("o2", Sum(Product(C, T1), Negate(Product(D, T2)), Product(A, T3))));

    [Fact]
    public void Scaled_temporaries_that_feed_linear_outputs_are_multiplied_by_the_reciprocal_once_per_output()
    {
        var before = ScaledThenMixed();
        var after = new ReciprocalDeferralPass().Run(before);
        AssertSameOutputs(before, after);
        Assert.Equal((5, 11, 1), (before.Statistics().Additions, before.Statistics().Multiplications, before.Statistics().Divisions));
        Assert.Equal((5, 10, 1), (after.Statistics().Additions, after.Statistics().Multiplications, after.Statistics().Divisions));
        // both outputs end with the multiplication by r, so the division overlaps their numerators
        Assert.All(after.Outputs, o => Assert.Contains(R, ((ProductExpr)o.Value).Children));
    }

    [Fact]
    public void A_scaled_temporary_read_under_a_square_or_a_quotient_stays_as_it_was()
    {
        var before = Block(
            Temp("r", Quotient(ConstantExpr.One, Sum(A, B))),
            Temp("t1", Product(A, R)),
            Out("o1", Product(T1, T1)),
            Out("o2", Quotient(C, Sum(T1, D))));
        var after = new ReciprocalDeferralPass().Run(before);
        Assert.Same(before, after);
    }

    [Fact]
    public void Skew_lines_closest_points_divide_both_numerators_with_two_multiplications_less_than_the_hand_formula_and_no_negation()
    {
        // (7.13): t1 = d2⌋(d1∧d2)⁻¹⌋(p2 − p1), t2 = d1⌋(d1∧d2)⁻¹⌋(p2 − p1). With the reciprocal of
        // |d1 × d2|² deferred it takes 23 multiplications and 1 division; dividing the two
        // numerators, 21 and 2, which the time model puts ahead: the multipliers, not the divider,
        // bound this kernel (ReciprocalDivisionPass).
        var request = new CodeGenerationRequest(
            r =>
            {
                var p1 = SymbolicMultivector.VectorVariables(E3, "p1");
                var d1 = SymbolicMultivector.VectorVariables(E3, "d1");
                var p2 = SymbolicMultivector.VectorVariables(E3, "p2");
                var d2 = SymbolicMultivector.VectorVariables(E3, "d2");
                var d = R(r, p2 - p1);
                var i = R(r, R(r, d1.Op(d2)).Inverse());
                var t1 = R(r, R(r, d2.Lcp(i)).Lcp(d));
                var t2 = R(r, R(r, d1.Lcp(i)).Lcp(d));
                return new SymbolicProgram([new SymbolicOutput("t1", t1.ScalarPart), new SymbolicOutput("t2", t2.ScalarPart)]);
            },
            VectorInputs(E3, "p1", "d1", "p2", "d2"),
            new Dictionary<string, string> { ["t1"] = "t1", ["t2"] = "t2" });
        var result = CodeGenerator.Generate(request);
        CodeGenerator_Kernels.AssertAgreesWithNumeric(result.Block, request, 13);
        Assert.Equal((15, 21, 2, 0), (result.Statistics.Additions, result.Statistics.Multiplications, result.Statistics.Divisions, result.Statistics.Calls));
        Assert.Equal(0, result.Statistics.Negations);
    }
}
