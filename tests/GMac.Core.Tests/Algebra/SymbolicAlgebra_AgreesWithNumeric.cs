using GMac.Core.Algebra;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Algebra;

/// <summary>The same algebra over symbolic scalars, evaluated afterwards, must give the numeric answers.</summary>
public class SymbolicAlgebra_AgreesWithNumeric
{
    private static (Multivector<Scalar> Symbolic, Multivector<double> Numeric) Pair(
        Frame frame, string prefix, Multivector<double> numeric, Dictionary<string, double> values)
    {
        var symbolic = SymbolicMultivector.Variables(frame, prefix, numeric.Terms.Select(t => t.Blade));
        foreach (var (blade, c) in numeric.Terms) values[SymbolicMultivector.VariableName(frame, prefix, blade)] = c;
        return (symbolic, numeric);
    }

    private static void AssertAgrees(Multivector<double> numeric, Multivector<Scalar> symbolic, Dictionary<string, double> values, string what)
    {
        var evaluated = symbolic.Evaluate(values);
        var scale = Math.Max(1e-300, numeric.Terms.Select(t => Math.Abs(t.Coefficient)).DefaultIfEmpty(1).Max());
        for (var id = 0; id < numeric.Frame.BladeCount; id++)
        {
            var b = new BasisBlade(id);
            var error = Math.Abs(numeric[b] - evaluated[b]) / scale;
            Assert.True(error <= 1e-12, $"{what}: blade {numeric.Frame.BladeName(b)} numeric {numeric[b]} symbolic {evaluated[b]} (relative error {error:E2})");
        }
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Every_operation_symbolic_then_numeric_equals_numeric(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(30);
        var values = new Dictionary<string, double>();
        var (sa, na) = Pair(frame, "a", r.General(frame), values);
        var (sb, nb) = Pair(frame, "b", r.General(frame), values);

        foreach (var kind in Enum.GetValues<ProductKind>())
            AssertAgrees(na.Product(kind, nb), sa.Product(kind, sb), values, kind.ToString());
        AssertAgrees(na + nb, sa + sb, values, "sum");
        AssertAgrees(na - nb * 2.5, sa - sb * Scalar.Constant(GMac.Core.Numerics.Rational.FromDouble(2.5)), values, "difference");
        AssertAgrees(na.Reverse(), sa.Reverse(), values, "reverse");
        AssertAgrees(na.GradeInvolution(), sa.GradeInvolution(), values, "grade involution");
        AssertAgrees(na.CliffordConjugate(), sa.CliffordConjugate(), values, "Clifford conjugate");
        AssertAgrees(na.Grade(2), sa.Grade(2), values, "grade 2");
        AssertAgrees(Multivector<double>.FromScalar(frame, na.QuasiNorm()), Multivector<Scalar>.FromScalar(frame, sa.QuasiNorm()), values, "quasi-norm");
        AssertAgrees(Multivector<double>.FromScalar(frame, na.Norm2()), Multivector<Scalar>.FromScalar(frame, sa.Norm2()), values, "norm²");

        var (sv, nv) = Pair(frame, "v", r.NonNullVector(frame), values);
        var (sw, nw) = Pair(frame, "w", r.NonNullVector(frame), values);
        var nVersor = nv.Gp(nw);
        var sVersor = sv.Gp(sw);
        AssertAgrees(nVersor.Inverse(), sVersor.Inverse(), values, "versor inverse");
        AssertAgrees(nVersor.Apply(na), sVersor.Apply(sa), values, "versor product");
        if (!frame.Metric.IsDegenerate)
        {
            AssertAgrees(na.Dual(), sa.Dual(), values, "dual");
            AssertAgrees(na.Undual(), sa.Undual(), values, "un-dual");
        }
    }

    [Fact]
    public void Thesis_example_4_2_gives_the_optimized_formulas()
    {
        var f = TestFrames.E3;
        var x = Scalar.Variable("x");
        var u = Multivector<Scalar>.Vector(f, Scalar.Sin(x), Scalar.Cos(x), 1);
        var v = Multivector<Scalar>.Vector(f, Scalar.Cos(x), Scalar.Sin(x), 1);
        var w = u.Op(v).Lcp(Multivector<Scalar>.Pseudoscalar(f).Inverse());

        // (4.11) with its sign slip mended: w is the cross product u × v, so w2 = u3 v1 − u1 v3 = w1
        // (the thesis prints w2 = −w1, which contradicts its own (4.8)–(4.9)).
        Assert.Same(Scalar.Cos(x) - Scalar.Sin(x), w["e1"]);
        Assert.Same(Scalar.Cos(x) - Scalar.Sin(x), w["e2"]);
        Assert.Same(Scalar.Sin(x) * Scalar.Sin(x) - Scalar.Cos(x) * Scalar.Cos(x), w["e3"]);
        Assert.Equal(3, w.TermCount);
    }

    [Fact]
    public void Normal_to_two_vectors_is_the_cross_product_with_six_multiplications_and_three_additions()
    {
        var f = TestFrames.E3;
        var u = SymbolicMultivector.VectorVariables(f, "u");
        var v = SymbolicMultivector.VectorVariables(f, "v");
        var w = u.Op(v).Lcp(Multivector<Scalar>.Pseudoscalar(f).Inverse());

        Scalar V(string n) => Scalar.Variable(n);
        Assert.Same(V("u.e2") * V("v.e3") - V("u.e3") * V("v.e2"), w["e1"]);
        Assert.Same(V("u.e3") * V("v.e1") - V("u.e1") * V("v.e3"), w["e2"]);
        Assert.Same(V("u.e1") * V("v.e2") - V("u.e2") * V("v.e1"), w["e3"]);

        var (adds, muls) = (0, 0);
        foreach (var (_, c) in w.Terms)
        {
            adds += c.Terms.Count - 1;
            foreach (var term in c.Terms)
            {
                muls += term.Monomial.Factors.Sum(fa => fa.Power) - 1;
                if (!term.Coefficient.Abs().IsOne) muls++;
            }
        }
        Assert.Equal((6, 3), (muls, adds));
    }

    [Fact]
    public void Coefficient_derivative_matches_finite_differences()
    {
        var f = TestFrames.Conformal;
        var t = Scalar.Variable("t");
        // a point moving on a helix, embedded as a conformal point (3.70)
        var pe = Multivector<Scalar>.Vector(f, 0, Scalar.Cos(t), Scalar.Sin(t), t * Scalar.Constant(new GMac.Core.Numerics.Rational(1, 3)), 0);
        var p = Multivector<Scalar>.Basis(f, "no") + pe + Multivector<Scalar>.Basis(f, "ni") * (pe.Gp(pe).ScalarPart * Scalar.Constant(new GMac.Core.Numerics.Rational(1, 2)));
        var dp = p.Derivative("t");
        foreach (var t0 in new[] { -1.3, 0.2, 2.9 })
        {
            var h = 1e-5;
            var numeric = (p.Evaluate(new Dictionary<string, double> { ["t"] = t0 + h }) - p.Evaluate(new Dictionary<string, double> { ["t"] = t0 - h })) * (1 / (2 * h));
            MultivectorAssert.Close(numeric, dp.Evaluate(new Dictionary<string, double> { ["t"] = t0 }), 1e-8);
        }
    }
}
