namespace GMac.Core.Algebra;

/// <summary>The bilinear products of basis blades (thesis Table 3-2), each a grade selection of the geometric product.</summary>
public enum ProductKind
{
    /// <summary>AB.</summary>
    Geometric,
    /// <summary>A ∧ B = ⟨AB⟩ of grade g(A)+g(B).</summary>
    Outer,
    /// <summary>A ⌋ B = ⟨AB⟩ of grade g(B)−g(A).</summary>
    LeftContraction,
    /// <summary>A ⌊ B = ⟨AB⟩ of grade g(A)−g(B).</summary>
    RightContraction,
    /// <summary>A * B = ⟨AB⟩₀.</summary>
    Scalar,
    /// <summary>A • B = ⟨AB⟩ of grade |g(B)−g(A)|.</summary>
    FatDot,
    /// <summary>Like the fat dot, but zero when either factor is a scalar.</summary>
    HestenesInner,
    /// <summary>½(AB − BA).</summary>
    Commutator,
    /// <summary>½(AB + BA).</summary>
    AntiCommutator,
}
