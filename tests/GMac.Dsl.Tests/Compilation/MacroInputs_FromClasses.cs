using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Compilation;

/// <summary>Inputs built from a class: variable coefficients from the caller, constants exact and signed by blade order.</summary>
public sealed class MacroInputs_FromClasses
{
    private const string Source = """
        define frame f as basis: {a, b, c} Euclidean end frame
        define subspace f.line as basis {a} end subspace
        define multivector class f.Fixed as line; b^a : 1/2; c : -3 end multivector class
        define macro Copy as inputs: { u : f.Fixed } outputs: { w : f.Multivector } performs: w = u; end macro
        """;

    [Fact]
    public void Symbolic_and_numeric_inputs_carry_the_same_exact_constants()
    {
        var project = SingleFileProject.Bind(Source);
        Assert.DoesNotContain(project.Diagnostics, d => d.IsError);
        var macro = project.Model.Macros["Copy"];
        var frames = new CoreFrames();
        var symbolic = MacroInputs.Build(frames, SymbolicDomain.Instance, macro, (input, blade) => Scalar.Variable($"{input.Name}{blade}")).Values.Single();
        var numeric = MacroInputs.Build(frames, DoubleDomain.Instance, macro, (_, blade) => 10.0 + blade).Values.Single();

        var (a, ab, c) = (new BasisBlade(0b001), new BasisBlade(0b011), new BasisBlade(0b100));
        Assert.Same(Scalar.Variable("u1"), symbolic[a]);
        Assert.Equal(Scalar.Constant(new Rational(-1, 2)), symbolic[ab]); // b^a = −a^b
        Assert.Equal(Scalar.Constant(-3), symbolic[c]);
        Assert.Equal(11.0, numeric[a]);
        Assert.Equal(-0.5, numeric[ab]);
        Assert.Equal(-3.0, numeric[c]);
        Assert.Equal(3, symbolic.Terms.Count());
        Assert.Equal(3, numeric.Terms.Count());
    }
}
