using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Rewrites;

/// <summary>How many of the given values (a block's outputs) read each atom at the top level of their terms.</summary>
public static class AtomSpread
{
    public static IReadOnlyDictionary<Atom, int> Of(IEnumerable<Scalar> values)
    {
        var spread = new Dictionary<Atom, int>();
        foreach (var v in values)
        foreach (var atom in v.Terms.SelectMany(t => t.Monomial.Factors).Select(f => f.Atom).Distinct())
            spread[atom] = spread.GetValueOrDefault(atom) + 1;
        return spread;
    }
}
