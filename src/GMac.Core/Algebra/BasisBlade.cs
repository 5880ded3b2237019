using System.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// A basis blade e_A = e_a1 ∧ e_a2 ∧ … ∧ e_ak (a1 &lt; a2 &lt; …) named by the bit pattern of its
/// basis vectors: bit i set means e_i is a factor. Id 0 is the scalar blade 1.
/// In a non-orthogonal frame the blade is the outer product, so it has a definite grade.
/// </summary>
public readonly record struct BasisBlade(int Id)
{
    public static readonly BasisBlade Scalar = new(0);

    public int Grade => BitOperations.PopCount((uint)Id);

    public bool Contains(int basisVectorIndex) => (Id & (1 << basisVectorIndex)) != 0;

    /// <summary>Indices of the basis vectors of this blade, ascending.</summary>
    public IEnumerable<int> BasisVectorIndices()
    {
        for (var bits = Id; bits != 0; bits &= bits - 1)
            yield return BitOperations.TrailingZeroCount(bits);
    }

    /// <summary>The sign of the reverse: (−1)^(k(k−1)/2).</summary>
    public static int ReverseSign(int grade) => (grade & 2) == 0 ? 1 : -1;

    /// <summary>The sign of the grade involution: (−1)^k.</summary>
    public static int GradeInvolutionSign(int grade) => (grade & 1) == 0 ? 1 : -1;

    /// <summary>The sign of the Clifford conjugate: (−1)^(k(k+1)/2).</summary>
    public static int CliffordConjugateSign(int grade) => ((grade + 1) & 2) == 0 ? 1 : -1;

    /// <summary>
    /// The sign of reordering the factors of e_a ∧ e_b into ascending order (e_a ∧ e_b = sign e_(a|b)
    /// when a and b share no basis vector): the parity of pairs (i in a, j in b) with i &gt; j.
    /// </summary>
    public static int OuterSign(int a, int b)
    {
        var swaps = 0;
        for (var shifted = a >> 1; shifted != 0; shifted >>= 1)
            swaps += BitOperations.PopCount((uint)(shifted & b));
        return (swaps & 1) == 0 ? 1 : -1;
    }
}
