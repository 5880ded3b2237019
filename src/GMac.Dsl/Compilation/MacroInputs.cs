using System.Numerics;
using GMac.Core.Algebra;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// The value of each macro input before evaluation, from its class: the coefficient of each
/// variable blade comes from the caller (a symbolic variable, a bound expression, a number), the
/// coefficient of each constant blade is the class's exact constant.
/// </summary>
public static class MacroInputs
{
    /// <param name="variable">The coefficient of an input's variable blade (given as a bit mask).</param>
    public static Dictionary<VariableSymbol, Multivector<T>> Build<T>(CoreFrames frames, IScalarDomain<T> domain, MacroSymbol macro,
        Func<VariableSymbol, int, T> variable)
        where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
    {
        var inputs = new Dictionary<VariableSymbol, Multivector<T>>();
        foreach (var input in macro.Inputs)
        {
            var cls = input.Class!;
            var terms = cls.VariableBlades.Select(b => (new BasisBlade(b), variable(input, b)))
                .Concat(cls.ConstantCoefficients.Select(c => (new BasisBlade(c.Blade), domain.FromRational(c.Value))));
            inputs[input] = Multivector<T>.FromTerms(frames[cls.Frame], terms);
        }
        return inputs;
    }
}
