using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Diagnostics;
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

    /// <summary>The symbolic evaluator, for callers that observe the evaluation (code generation).</summary>
    public MacroEvaluator<Scalar> Evaluator => _evaluator;

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

    /// <summary>Compiles, turning an evaluation failure (e.g. the inverse of a null blade) into a diagnostic.</summary>
    public bool TryCompile(MacroSymbol macro, IReadOnlyDictionary<string, Scalar>? coefficientBindings,
        out IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> outputs, out Diagnostic? diagnostic)
    {
        try
        {
            outputs = Compile(macro, coefficientBindings);
            diagnostic = null;
            return true;
        }
        catch (MacroEvaluationException e)
        {
            outputs = new Dictionary<VariableSymbol, Multivector<Scalar>>();
            diagnostic = DiagnosticBag.EvaluationError(e.Span, e.Message);
            return false;
        }
    }

    /// <summary>
    /// <paramref name="relations"/> extended with ⟨A Ã⟩₀ = 1 for every input of a
    /// <c>normalized</c> class, solved for the square of its scalar coefficient (w² for a
    /// rotor), so that the simplifier can reduce e.g. w² + x² − y² − z² to 1 − 2(y² + z²).
    /// </summary>
    public static SideRelations NormalizationRelations(MacroSymbol macro,
        IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> inputs, SideRelations relations)
    {
        foreach (var input in macro.Inputs.Where(i => i.Class is { IsNormalized: true }))
        {
            var value = inputs[input];
            var pivot = value.Terms.Select(t => t.Coefficient).FirstOrDefault(c => c.Variables.Count == 1 && c.IsMonomial);
            if (pivot is null) continue;
            relations = relations.With(value.QuasiNorm(), Scalar.One, pivot * pivot);
        }
        return relations;
    }

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
