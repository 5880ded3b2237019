using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>Keeps only the listed blades of the operand (cast to grades, subspace or class).</summary>
public sealed record BoundCast(CastKind Kind, BoundExpression Operand, IReadOnlyList<int> Blades, Symbol? Target,
    ExpressionType Type, SourceSpan Span) : BoundExpression(Type, Span);
