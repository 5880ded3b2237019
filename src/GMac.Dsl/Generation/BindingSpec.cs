namespace GMac.Dsl.Generation;

/// <summary>
/// One <c>//GMac.Bind</c> line, already split by the binding-point reader. <see cref="Line"/>
/// locates it for diagnostics.
/// </summary>
public abstract record BindingSpec(int Line, int Column);

/// <summary>
/// <c>Bind("u.e1", …)</c>: one coefficient. For an input, <see cref="Value"/> is a scalar
/// expression whose <c>&lt;…&gt;</c> parts are target-language expressions (the string form) or a
/// bare target-language expression; for an output it is the assignable target.
/// </summary>
public sealed record CoefficientBindingSpec(string Parameter, string Blade, string Value, bool IsTemplate, int Line, int Column) : BindingSpec(Line, Column);

/// <summary><c>Bind("u", "Vector3D", "obj")</c>: a whole parameter through a class binding.</summary>
public sealed record ClassBindingSpec(string Parameter, string ClassBinding, string Target, int Line, int Column) : BindingSpec(Line, Column);

/// <summary><c>AssumeMin/AssumeMax("expr", "value")</c>: a bound on a bound target-language expression.</summary>
public sealed record AssumptionSpec(string Expression, Core.Numerics.Rational Value, bool IsMinimum, int Line, int Column) : BindingSpec(Line, Column);
