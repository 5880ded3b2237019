namespace GMac.Dsl.Semantics;

/// <summary>One <c>parameter : value</c> of a call statement: an input gets a value, an output a target.</summary>
public sealed record BoundCallBinding(VariableSymbol Parameter, BoundExpression? Value, VariableSymbol? Target);
