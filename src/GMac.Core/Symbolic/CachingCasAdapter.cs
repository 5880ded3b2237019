namespace GMac.Core.Symbolic;

/// <summary>
/// Puts a <see cref="SimplificationCache"/> in front of a CAS adapter: every answer is cached under
/// the adapter name, the canonical text of the assumptions and of the expression.
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
        var key = KeyOf(expression, assumptions);
        if (Cache.TryGet(key, out var cached)) return cached;
        var result = Inner.Simplify(expression, assumptions);
        Cache.Add(key, result);
        return result;
    }

    public string KeyOf(Scalar expression, Assumptions assumptions) =>
        $"{Inner.Name} | {assumptions.Key} | {expression}";
}
