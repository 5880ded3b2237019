namespace GMac.Dsl.Generation;

/// <summary>
/// A host-language expression the generated code reads or writes, as written.
/// <see cref="HasEffects"/> (a call, an increment, an assignment: decided by the host) makes an
/// input read once into a local instead of at every use.
/// </summary>
public sealed record HostExpression(string Text, bool HasEffects) : BindingValue(Text)
{
    public override string? Target => Text.Trim();
}
