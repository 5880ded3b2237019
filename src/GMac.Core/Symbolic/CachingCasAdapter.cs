namespace GMac.Core.Symbolic;

/// <summary>
/// Puts a <see cref="SimplificationCache"/> in front of a CAS adapter: every answer is cached under
/// the adapter name, the canonical text of the assumptions and the structural fingerprint of the
/// expression. The fingerprint, not the expression's text, keys the answer: the text of a large
/// expression with shared subexpressions runs to megabytes, and printing it cost more than simplifying.
/// </summary>
public sealed class CachingCasAdapter(ICasAdapter inner, SimplificationCache cache) : ICasAdapter
{
    public ICasAdapter Inner { get; } = inner ?? throw new ArgumentNullException(nameof(inner));

    public SimplificationCache Cache { get; } = cache ?? throw new ArgumentNullException(nameof(cache));

    public string Name => Inner.Name;

    public Scalar Parse(string text) => Inner.Parse(text);

    public Scalar Simplify(Scalar expression, Assumptions assumptions)
    {
        ArgumentNullException.ThrowIfNull(expression);
        ArgumentNullException.ThrowIfNull(assumptions);
        // Constants and variables are already as simple as they get.
        if (expression.IsConstant) return expression;
        // Equal expressions are one object, so a repeated question is answered without making a key.
        var answers = _byIdentity.GetValue(expression, _ => new Dictionary<string, Scalar>(StringComparer.Ordinal));
        lock (answers)
        {
            if (answers.TryGetValue(assumptions.Key, out var known))
            {
                Interlocked.Increment(ref _identityHits);
                return known;
            }
        }
        var key = KeyOf(expression, assumptions);
        if (!Cache.TryGet(key, out var result))
        {
            result = Inner.Simplify(expression, assumptions);
            Cache.Add(key, result);
        }
        lock (answers) answers[assumptions.Key] = result;
        return result;
    }

    private readonly System.Runtime.CompilerServices.ConditionalWeakTable<Scalar, Dictionary<string, Scalar>> _byIdentity = new();
    private long _identityHits;

    /// <summary>Questions answered from this process's identity table, before any text key was made.</summary>
    public long IdentityHits => Interlocked.Read(ref _identityHits);

    /// <summary>All answers that did not need the simplifier: identity hits plus the text cache's hits.</summary>
    public long TotalHits => IdentityHits + Cache.Hits;

    public string KeyOf(Scalar expression, Assumptions assumptions) =>
        $"{Inner.Name} | {assumptions.Key} | #{expression.Fingerprint:x32}";
}
