namespace GMac.Dsl.Generation;

/// <summary>
/// <c>//GMac.Fma(true);</c>: whether the binding point's code fuses a product with the sum it is
/// added to (one rounding instead of two). <see cref="Enabled"/> is null when the argument is not
/// <c>true</c> or <c>false</c>; <see cref="Text"/> is the argument as written, for the message.
/// </summary>
public sealed record FusedMultiplyAddSpec(bool? Enabled, string Text, int Line, int Column) : BindingSpec(Line, Column);
