using GMac.Dsl.Generation;

namespace GMac.Dsl.Tests.Support;

/// <summary>
/// Binding values built in their typed form, as the C# host layer hands them to the generator (the
/// DSL's tests read no host-language text).
/// </summary>
internal static class BindingValues
{
    /// <summary>What the host reads from <c>"&lt;name&gt;"</c>: a template of one hole, also an output target.</summary>
    public static TemplateValue Hole(string name) => new($"<{name}>", [new TemplateHole(new HostExpression(name, HasEffects: false))], name);

    /// <summary>What the host reads from <c>"factor&lt;name&gt;"</c> (e.g. <c>"-&lt;R.zx&gt;"</c>, <c>"2*&lt;R.zx&gt;"</c>): a scaled hole, no output target.</summary>
    public static TemplateValue ScaledHole(string factor, string name) =>
        new($"{factor}<{name}>", [new ScalarTextPart(factor), new TemplateHole(new HostExpression(name, HasEffects: false))], Target: null);

    /// <summary>What the host reads from a quoted value without holes, such as <c>"0"</c>.</summary>
    public static TemplateValue Scalar(string text) => new(text, [new ScalarTextPart(text)], Target: null);

    /// <summary>A bare host expression without effects, such as <c>cr</c>.</summary>
    public static HostExpression Bare(string text) => new(text, HasEffects: false);
}
