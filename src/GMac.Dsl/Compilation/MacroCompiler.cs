using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// Evaluates macros on symbolic scalars (inputs from <see cref="MacroInputs"/>), with the
/// derivative rule of the symbolic domain and the side relations of normalized classes.
/// </summary>
public sealed class MacroCompiler(CoreFrames frames)
{
    private readonly MacroEvaluator<Scalar> _evaluator = new(frames, SymbolicDomain.Instance, Differentiate);

    /// <summary>The symbolic evaluator, for callers that observe the evaluation (code generation).</summary>
    public MacroEvaluator<Scalar> Evaluator => _evaluator;

    public CoreFrames Frames { get; } = frames;

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

    private static Multivector<Scalar>? Differentiate(Multivector<Scalar> operand, Scalar coefficient)
    {
        if (coefficient.Variables.Count != 1) return null;
        var name = coefficient.Variables.First();
        return ReferenceEquals(coefficient, Scalar.Variable(name)) ? operand.Derivative(name) : null;
    }
}
