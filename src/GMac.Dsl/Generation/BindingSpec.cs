namespace GMac.Dsl.Generation;

/// <summary>
/// One <c>//GMac.Bind</c> line, already split by the binding-point reader. <see cref="Line"/>
/// locates it for diagnostics.
/// </summary>
public abstract record BindingSpec(int Line, int Column);

/// <summary>
/// <c>Bind("u.e1", …)</c>: one coefficient. For an input, <see cref="Value"/> is what it reads; for
/// an output, its <see cref="BindingValue.Target"/> is where it is written.
/// </summary>
public sealed record CoefficientBindingSpec(string Parameter, string Blade, BindingValue Value, int Line, int Column) : BindingSpec(Line, Column);

/// <summary>
/// <c>Bind("u", "Vector3D", "obj")</c>: a whole parameter through a class binding.
/// <see cref="TargetHasEffects"/> (decided by the host) makes an input object read once.
/// </summary>
public sealed record ClassBindingSpec(string Parameter, string ClassBinding, string Target, int Line, int Column) : BindingSpec(Line, Column)
{
    public bool TargetHasEffects { get; init; }
}

/// <summary><c>AssumeMin/AssumeMax("expr", "value")</c>: a bound on a bound target-language expression.</summary>
public sealed record AssumptionSpec(string Expression, Core.Numerics.Rational Value, bool IsMinimum, int Line, int Column) : BindingSpec(Line, Column);
