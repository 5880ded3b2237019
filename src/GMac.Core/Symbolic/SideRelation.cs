namespace GMac.Core.Symbolic;

/// <summary>
/// One polynomial rewrite: every monomial divisible by <see cref="Pattern"/> has that factor
/// replaced by <see cref="Replacement"/> (e.g. w^2 → 1 - x^2 - y^2 - z^2 for a unit rotor).
/// </summary>
public sealed record SideRelation(Monomial Pattern, Scalar Replacement)
{
    public override string ToString() => $"{Pattern} -> {Replacement}";
}
