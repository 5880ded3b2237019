using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Tests.Support;

/// <summary>A macro evaluated on symbolic inputs whose variable coefficients are named like <c>u.e1</c>.</summary>
internal static class SymbolicMacro
{
    public static Dictionary<VariableSymbol, Multivector<Scalar>> Inputs(CoreFrames frames, MacroSymbol macro) =>
        MacroInputs.Build(frames, SymbolicDomain.Instance, macro, (input, blade) =>
            Scalar.Variable(SymbolicMultivector.VariableName(frames[input.Class!.Frame], input.Name, new BasisBlade(blade))));

    public static IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> Compile(MacroSymbol macro)
    {
        var frames = new CoreFrames();
        return new MacroCompiler(frames).Evaluator.Evaluate(macro, Inputs(frames, macro));
    }
}
