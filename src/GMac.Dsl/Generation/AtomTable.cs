using GMac.Core.CodeGeneration;
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

    private readonly List<string> _once = [];

    /// <summary>Expressions with effects, each evaluated once before the code (see <see cref="CodeBlock.EvaluatedOnce"/>).</summary>
    public IReadOnlyList<string> EvaluatedOnce => _once;

    /// <summary>
    /// The text that reads the value of <paramref name="text"/>, evaluated once: a new placeholder per
    /// call, so the same call written twice runs twice, as it would in hand-written code.
    /// </summary>
    public string Once(string text)
    {
        _once.Add(text.Trim());
        return CodeBlock.EvaluatedOnceMarker(_once.Count - 1);
    }

    /// <summary>The texts with placeholders replaced by what they evaluate: for messages and for matching bind lines.</summary>
    public IReadOnlyDictionary<string, string> DisplayTexts()
    {
        if (_once.Count == 0) return _texts;
        return _texts.ToDictionary(x => x.Key, x =>
        {
            var text = x.Value;
            for (var k = 0; k < _once.Count; k++) text = text.Replace(CodeBlock.EvaluatedOnceMarker(k), _once[k], StringComparison.Ordinal);
            return text;
        }, StringComparer.Ordinal);
    }
}
