using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>A scalar function; multivector arguments contribute their scalar part.</summary>
public sealed record BoundScalarFunctionCall(ScalarFunction Function, IReadOnlyList<BoundExpression> Arguments, SourceSpan Span)
    : BoundExpression(ExpressionType.Scalar, Span);
