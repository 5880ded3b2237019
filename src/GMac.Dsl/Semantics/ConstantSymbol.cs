using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A constant multivector of one frame.</summary>
public sealed class ConstantSymbol(string name, SourceSpan declaration, FrameSymbol frame) : Symbol(name, declaration)
{
    public FrameSymbol Frame { get; } = frame;
    public IReadOnlyList<CoefficientValue> Coefficients { get; internal set; } = [];
    public string QualifiedName => $"{Frame.Name}.{Name}";
}
