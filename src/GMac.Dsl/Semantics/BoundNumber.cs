using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

public sealed record BoundNumber(Rational Value, SourceSpan Span) : BoundExpression(ExpressionType.Scalar, Span);
