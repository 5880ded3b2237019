using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary><c>frame.multivector { blade : scalar; … }</c>.</summary>
public sealed record BoundMultivectorConstruction(FrameSymbol Frame, IReadOnlyList<CoefficientValue> Coefficients,
    ExpressionType Type, SourceSpan Span) : BoundExpression(Type, Span);
