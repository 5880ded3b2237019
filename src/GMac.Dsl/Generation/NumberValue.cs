using GMac.Core.Numerics;

namespace GMac.Dsl.Generation;

/// <summary>A bare number (<c>GMac.Bind("s.1", 2)</c>): a constant input.</summary>
public sealed record NumberValue(string Text, Rational Value) : BindingValue(Text)
{
    /// <summary>A number is no target; the host's check says so in its own words.</summary>
    public override string? Target => Text.Trim();
}
