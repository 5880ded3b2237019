namespace GMac.Dsl.Semantics;

/// <summary>A blade with a scalar expression for its coefficient.</summary>
public sealed record CoefficientValue(BladeReference Blade, BoundExpression Value);
