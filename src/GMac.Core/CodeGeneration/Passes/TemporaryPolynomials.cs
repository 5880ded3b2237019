using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// The polynomials of the inputs that a block's temporaries hold, each looked through the
/// temporaries it reads and lifted once. A temporary that holds anything else (a quotient, a
/// call), is assigned more than once, or whose polynomial passes the limits has none
/// (<see cref="Of"/> is null), and stays a variable of its own in the polynomials that read it.
/// </summary>
internal sealed class TemporaryPolynomials(CodeBlock block, int maxTerms, int maxNodes = int.MaxValue)
{
    private readonly Dictionary<string, Scalar?> _lifted = new(StringComparer.Ordinal);

    /// <summary>The single-assigned temporaries' values, by name.</summary>
    public Dictionary<string, Expr> Definitions { get; } = block.Temporaries
        .GroupBy(t => t.Target, StringComparer.Ordinal).Where(g => g.Count() == 1)
        .ToDictionary(g => g.Key, g => g.Single().Value, StringComparer.Ordinal);

    public bool IsTemporary(string name) => Definitions.ContainsKey(name);

    /// <summary>The polynomial temporary <paramref name="name"/> holds, or null (see the class).</summary>
    public Scalar? Of(string name)
    {
        if (!Definitions.TryGetValue(name, out var value)) return null;
        if (_lifted.TryGetValue(name, out var known)) return known;
        _lifted[name] = null; // single assignment: no cycle, but guard anyway
        var lifted = value.Size <= maxNodes ? PolynomialLifting.LiftThrough(value, Of) : null;
        return _lifted[name] = lifted is not null && lifted.Terms.Count <= maxTerms ? lifted : null;
    }
}
