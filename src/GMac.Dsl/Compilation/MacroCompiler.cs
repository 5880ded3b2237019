using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// Compiles a macro to symbolic multivectors: each input coefficient is a symbolic
/// variable (named like <c>u.e1</c>, see <see cref="SymbolicMultivector.VariableName"/>),
/// a constant coefficient of the input's class, or a value given in the binding.
/// </summary>
public sealed class MacroCompiler(CoreFrames frames)
{
    private readonly MacroEvaluator<Scalar> _evaluator = new(frames, SymbolicDomain.Instance, Differentiate);

    public CoreFrames Frames { get; } = frames;

    /// <summary>The symbolic value of each input before evaluation, for the given bindings.</summary>
    public Dictionary<VariableSymbol, Multivector<Scalar>> BindInputs(MacroSymbol macro,
        IReadOnlyDictionary<string, Scalar>? coefficientBindings = null)
    {
        var inputs = new Dictionary<VariableSymbol, Multivector<Scalar>>();
        foreach (var input in macro.Inputs)
        {
            var cls = input.Class!;
            var frame = Frames[cls.Frame];
            var terms = new List<(BasisBlade, Scalar)>();
            foreach (var id in cls.VariableBlades)
            {
                var blade = new BasisBlade(id);
                var key = $"{input.Name}.{frame.BladeName(blade)}";
                terms.Add((blade, coefficientBindings is not null && coefficientBindings.TryGetValue(key, out var bound)
                    ? bound
                    : Scalar.Variable(SymbolicMultivector.VariableName(frame, input.Name, blade))));
            }
            foreach (var c in cls.ConstantCoefficients)
            {
                var value = ConstantValue(c.Value);
                terms.Add((new BasisBlade(c.Blade.Mask), c.Blade.Sign < 0 ? -value : value));
            }
            inputs[input] = Multivector<Scalar>.FromTerms(frame, terms);
        }
        return inputs;
    }

    public IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> Compile(MacroSymbol macro,
        IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> inputs) => _evaluator.Evaluate(macro, inputs);

    public IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> Compile(MacroSymbol macro,
        IReadOnlyDictionary<string, Scalar>? coefficientBindings = null) => Compile(macro, BindInputs(macro, coefficientBindings));

    private static Scalar ConstantValue(BoundExpression value) =>
        Folding.TryFold(value) is { } r ? Scalar.Constant(r)
        : throw new MacroEvaluationException(value.Span, "class constants must be exact numbers");

    private static Multivector<Scalar>? Differentiate(Multivector<Scalar> operand, Scalar coefficient)
    {
        if (coefficient.Variables.Count != 1) return null;
        var name = coefficient.Variables.First();
        return ReferenceEquals(coefficient, Scalar.Variable(name)) ? operand.Derivative(name) : null;
    }
}
