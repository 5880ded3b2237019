using GMac.Dsl.Generation;

namespace GMac.Cli.BindingPoints;

/// <summary>
/// One <c>//GMac.</c> line of a binding point, read into a spec. <see cref="TargetIsAssignable"/>
/// says whether its C# text could receive a value, which matters once the parameter turns out to be an output.
/// </summary>
internal sealed record BindingLine(BindingSpec Spec, bool TargetIsAssignable, string TargetText);
