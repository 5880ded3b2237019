using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>
/// A multivector class: the blades with variable coefficients, blades with
/// constant coefficients, and whether the class is normalized (⟨A Ã⟩₀ = 1).
/// </summary>
public sealed class MultivectorClassSymbol(string name, SourceSpan declaration, FrameSymbol frame) : Symbol(name, declaration)
{
    public FrameSymbol Frame { get; } = frame;
    public IReadOnlyList<int> VariableBlades { get; internal set; } = [];
    public IReadOnlyList<ClassConstant> ConstantCoefficients { get; internal set; } = [];
    public bool IsNormalized { get; internal set; }
    public bool IsImplicit { get; internal set; }

    /// <summary>Every blade that may be non-zero in a member of the class.</summary>
    public IEnumerable<int> AllBlades => VariableBlades.Concat(ConstantCoefficients.Select(c => c.Blade)).Distinct();

    public int GradeMask => AllBlades.Aggregate(0, (m, b) => m | (1 << System.Numerics.BitOperations.PopCount((uint)b)));

    public string QualifiedName => $"{Frame.Name}.{Name}";
}
