namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    /// <summary>The largest frame dimension with a closed-form general inverse.</summary>
    public const int GeneralInverseMaxDimension = 5;

    /// <summary>
    /// The inverse of any invertible multivector of a frame of at most 5 dimensions, as
    /// adj(A) / ⟨A adj(A)⟩₀ with the adjugate made of involutions (Hitzer and Sangwine,
    /// "Multivector and multivector matrix inverses in real Clifford algebras", 2017):
    /// n ≤ 2: adj(A) = Ā; n = 3: Ā Â Ã; n = 4: Ā m₃₄(AĀ); n = 5: Ā Â Ã m₁₄(AĀÂÃ), where Ā is the
    /// Clifford conjugate and mⱼₖ negates grades j and k. A adj(A) is then a scalar in every metric
    /// (the identity is polynomial, so it holds for degenerate and non-orthogonal metrics too), and
    /// A is invertible exactly where that scalar is non-zero.
    /// </summary>
    /// <param name="name">
    /// Applied to each intermediate product before it is used again; symbolic callers name it, so
    /// that the adjugate is built from named partial results instead of one expanded polynomial.
    /// </param>
    public Multivector<T> GeneralInverse(Func<Multivector<T>, Multivector<T>>? name = null)
    {
        var n = Frame.Dimension;
        if (n > GeneralInverseMaxDimension)
            throw new AlgebraException(Frame.Name,
                $"the general inverse has closed forms up to {GeneralInverseMaxDimension} dimensions, and this frame has {n}; use inverse(A) for versors and blades.");
        if (IsZero)
            throw new AlgebraException(Frame.Name, "the zero multivector has no inverse.") { NotInvertible = true };
        name ??= static m => m;
        var adjugate = Adjugate(n, name);
        var norm = Sp(adjugate).ScalarPart;
        if (T.IsZero(norm))
            throw new AlgebraException(Frame.Name, "it has no inverse: A adj(A) is zero, with adj(A) the adjugate made of its involutions.") { NotInvertible = true };
        return adjugate / norm;
    }

    /// <summary>adj(A) with A adj(A) a scalar, for a frame of dimension <paramref name="n"/> ≤ 5.</summary>
    private Multivector<T> Adjugate(int n, Func<Multivector<T>, Multivector<T>> name)
    {
        var conjugate = CliffordConjugate();
        switch (n)
        {
            case <= 2:
                return conjugate;
            case 3:
                return name(name(conjugate.Gp(GradeInvolution())).Gp(Reverse()));
            case 4:
                return name(conjugate.Gp(NegateGrades(name(Gp(conjugate)), 3, 4)));
            default:
                var three = name(name(conjugate.Gp(GradeInvolution())).Gp(Reverse()));
                return name(three.Gp(NegateGrades(name(Gp(three)), 1, 4)));
        }
    }

    private static Multivector<T> NegateGrades(Multivector<T> m, int j, int k) => m.SignByGrade((1 << j) | (1 << k));
}
