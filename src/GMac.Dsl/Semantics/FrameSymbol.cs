using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;

namespace GMac.Dsl.Semantics;

/// <summary>
/// A frame: named basis vectors and their inner product matrix (IPM). A frame
/// derived from another keeps that source and the basis change matrix (BCM)
/// whose row i holds the new basis vector i in source coordinates.
/// </summary>
public sealed class FrameSymbol(string name, SourceSpan declaration, IReadOnlyList<string> basisNames)
    : Symbol(name, declaration)
{
    public IReadOnlyList<string> BasisNames { get; } = basisNames;
    public int Dimension => BasisNames.Count;
    public FrameKind Kind { get; internal set; }
    public RationalMatrix InnerProductMatrix { get; internal set; } = RationalMatrix.Identity(0);
    public FrameSymbol? Source { get; internal set; }
    public RationalMatrix? BasisChangeMatrix { get; internal set; }

    internal Dictionary<string, Symbol> Members { get; } = new(StringComparer.Ordinal);

    /// <summary>The implicit class of all blades of the frame.</summary>
    public MultivectorClassSymbol MultivectorClass { get; internal set; } = null!;

    public int IndexOfBasis(string basisName)
    {
        for (var i = 0; i < BasisNames.Count; i++)
            if (BasisNames[i] == basisName) return i;
        return -1;
    }

    public IEnumerable<Symbol> MemberSymbols => Members.Values;

    /// <summary>Name of the blade with the given basis-vector bit mask, in basis order.</summary>
    public string BladeName(int mask)
    {
        if (mask == 0) return "1";
        var parts = new List<string>();
        for (var i = 0; i < Dimension; i++)
            if ((mask & (1 << i)) != 0) parts.Add(BasisNames[i]);
        return string.Join("^", parts);
    }
}
