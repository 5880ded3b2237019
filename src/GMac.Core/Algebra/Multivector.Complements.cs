namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    // ---- complements and the regressive product --------------------------------------------------
    // Defined on basis-blade masks with reordering signs only, never through the metric, so they exist
    // where the dual does not (a degenerate metric such as projective 3D with e0² = 0).

    /// <summary>
    /// The right complement ★A: linear, with e_S ∧ ★e_S = I (the pseudoscalar in the frame's basis
    /// order) for every basis blade e_S, so ★e_S = σ(S, S̄) e_S̄ where σ is the sign of e_S ∧ e_S̄ = σ I.
    /// </summary>
    public Multivector<T> RightComplement() => Complement(right: true);

    /// <summary>
    /// The left complement: ★e_S ∧ e_S = I, so it is σ(S̄, S) e_S̄. It is the inverse of the right one;
    /// applying the right complement twice gives (−1)^(k(n−k)) on grade k.
    /// </summary>
    public Multivector<T> LeftComplement() => Complement(right: false);

    /// <summary>The regressive product A ∨ B = ★⁻¹(★A ∧ ★B), ★ the right complement and ★⁻¹ the left one.</summary>
    public Multivector<T> Regressive(Multivector<T> b)
    {
        RequireSameFrame(this, b, "take the regressive product of");
        return RightComplement().Op(b.RightComplement()).LeftComplement();
    }

    private Multivector<T> Complement(bool right)
    {
        var all = Frame.Pseudoscalar.Id;
        return FromTerms(Frame, Terms.Select(t =>
        {
            var (s, c) = (t.Blade.Id, all & ~t.Blade.Id);
            var sign = right ? BasisBlade.OuterSign(s, c) : BasisBlade.OuterSign(c, s);
            return (new BasisBlade(c), sign > 0 ? t.Coefficient : -t.Coefficient);
        }));
    }
}
