using GMac.Core.Symbolic;

namespace GMac.Dsl.Generation;

/// <summary>
/// The target-language expressions a binding point reads, each behind one symbolic variable;
/// the same text (ignoring surrounding white space) always maps to the same variable.
/// </summary>
internal sealed class AtomTable
{
    private readonly Dictionary<string, string> _byText = new(StringComparer.Ordinal);
    private readonly Dictionary<string, string> _texts = new(StringComparer.Ordinal);

    public IReadOnlyDictionary<string, string> Texts => _texts;

    public Scalar For(string text)
    {
        text = text.Trim();
        if (!_byText.TryGetValue(text, out var name))
        {
            name = $"bp_in{_texts.Count}";
            _byText[text] = name;
            _texts[name] = text;
        }
        return Scalar.Variable(name);
    }

    public string? Find(string text) => _byText.TryGetValue(text.Trim(), out var name) ? name : null;
}
