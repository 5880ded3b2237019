using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>
/// A class binding: scalar functions of members of a target-language object
/// (written <c>&lt;x&gt;</c>) for blade coefficients of one frame, with optional limits.
/// </summary>
public sealed class ClassBindingSymbol(string name, SourceSpan declaration) : Symbol(name, declaration)
{
    public FrameSymbol Frame { get; internal set; } = null!;
    public IReadOnlyList<CoefficientValue> Coefficients { get; internal set; } = [];
    public IReadOnlyDictionary<string, Rational> Minimums { get; internal set; } = new Dictionary<string, Rational>();
    public IReadOnlyDictionary<string, Rational> Maximums { get; internal set; } = new Dictionary<string, Rational>();
}
