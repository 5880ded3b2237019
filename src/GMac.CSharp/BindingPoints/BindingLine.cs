using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>One <c>//GMac.</c> line of a binding point, read into a spec (its C# text is checked by <see cref="BindingTextCheck"/>).</summary>
internal sealed record BindingLine(BindingSpec Spec);
