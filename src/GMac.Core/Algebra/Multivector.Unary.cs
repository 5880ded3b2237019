using System.Numerics;

namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    // ---- involutions and grades ------------------------------------------------------------------

    /// <summary>Negates the grades whose bit is set in <paramref name="negatedGrades"/>.</summary>
    private Multivector<T> SignByGrade(int negatedGrades)
    {
        if (_dense is not null) return DenseByGrade(-1, negatedGrades);
        var cs = new T[_coefficients.Length];
        for (var i = 0; i < cs.Length; i++)
            cs[i] = (negatedGrades & (1 << BitOperations.PopCount((uint)_ids[i]))) == 0 ? _coefficients[i] : -_coefficients[i];
        return new Multivector<T>(Frame, _ids, cs);
    }

    /// <summary>The grades 0..32 whose sign is −1, as a bit mask.</summary>
    private static int NegatedGrades(Func<int, int> sign)
    {
        var mask = 0;
        for (var k = 0; k < 32; k++)
            if (sign(k) < 0) mask |= 1 << k;
        return mask;
    }

    private static readonly int ReverseNegated = NegatedGrades(BasisBlade.ReverseSign);
    private static readonly int GradeInvolutionNegated = NegatedGrades(BasisBlade.GradeInvolutionSign);
    private static readonly int CliffordConjugateNegated = NegatedGrades(BasisBlade.CliffordConjugateSign);

    /// <summary>Ã: reverses the order of vector factors, (−1)^(k(k−1)/2) on grade k.</summary>
    public Multivector<T> Reverse() => SignByGrade(ReverseNegated);

    /// <summary>Â: (−1)^k on grade k.</summary>
    public Multivector<T> GradeInvolution() => SignByGrade(GradeInvolutionNegated);

    /// <summary>A†: (−1)^(k(k+1)/2) on grade k.</summary>
    public Multivector<T> CliffordConjugate() => SignByGrade(CliffordConjugateNegated);

    /// <summary>⟨A⟩ₖ, the grade-k part.</summary>
    public Multivector<T> Grade(int k)
    {
        if (_dense is not null) return DenseByGrade((uint)k < 32 ? 1 << k : 0, 0);
        var count = 0;
        foreach (var id in _ids)
            if (BitOperations.PopCount((uint)id) == k) count++;
        if (count == _ids.Length) return this;
        var ids = new int[count];
        var cs = new T[count];
        for (int i = 0, j = 0; i < _ids.Length; i++)
        {
            if (BitOperations.PopCount((uint)_ids[i]) != k) continue;
            ids[j] = _ids[i];
            cs[j++] = _coefficients[i];
        }
        return new Multivector<T>(Frame, ids, cs);
    }

    public Multivector<T> SelectGrades(Func<int, bool> keep)
    {
        if (_dense is not null) return DenseByGrade(GradeMask(keep), 0);
        var ids = new int[_ids.Length];
        var cs = new T[_ids.Length];
        var k = 0;
        for (var i = 0; i < _ids.Length; i++)
        {
            if (!keep(BitOperations.PopCount((uint)_ids[i]))) continue;
            ids[k] = _ids[i];
            cs[k++] = _coefficients[i];
        }
        return Trimmed(Frame, ids, cs, k);
    }

    /// <summary>The grades 0..n of this frame that <paramref name="keep"/> accepts, as a bit mask.</summary>
    private int GradeMask(Func<int, bool> keep)
    {
        var mask = 0;
        for (var k = 0; k <= Frame.Dimension; k++)
            if (keep(k)) mask |= 1 << k;
        return mask;
    }

    // ---- norms ---------------------------------------------------------------------------------

    /// <summary>The quasi-norm [[A]] = ⟨A Ã⟩₀ (3.59); may be negative or zero in non-Euclidean frames.</summary>
    public T QuasiNorm() => Sp(Reverse()).ScalarPart;

    /// <summary>
    /// ‖A‖² = Σₖ |⟨Aₖ Ãₖ⟩₀| (3.60). In a positive-definite frame each term is already non-negative,
    /// so the absolute values are left out (this keeps symbolic results polynomial).
    /// </summary>
    public T Norm2()
    {
        var positive = Frame.Metric.IsPositiveDefinite;
        var sum = T.Zero;
        foreach (var k in Grades)
        {
            var part = Grade(k);
            var q = part.QuasiNorm();
            sum += positive ? q : T.Abs(q);
        }
        return sum;
    }

    /// <summary>‖A‖ = √‖A‖² (3.60).</summary>
    public T Norm() => T.Sqrt(Norm2());

    // ---- inverse, dual, versor product -------------------------------------------------------------

    /// <summary>
    /// The inverse of a versor or blade, Ṽ / [[V]] (3.61). A null versor (quasi-norm zero) has none.
    /// </summary>
    public Multivector<T> Inverse()
    {
        if (IsZero)
            throw new AlgebraException(Frame.Name, "the zero multivector has no inverse.");
        var reverse = Reverse();
        var q = QuasiNorm();
        if (T.IsZero(q))
            throw new AlgebraException(Frame.Name, $"cannot invert the null versor or blade {this}: its quasi-norm ⟨V Ṽ⟩₀ is zero.");
        return reverse / q;
    }

    /// <summary>The pseudoscalar I of the frame.</summary>
    public static Multivector<T> Pseudoscalar(Frame frame) => Basis(frame, frame.Pseudoscalar);

    /// <summary>A* = A ⌋ I⁻¹ (3.65).</summary>
    public Multivector<T> Dual() => Dual(Pseudoscalar(Frame));

    /// <summary>The dual with respect to a non-null blade B: A ⌋ B⁻¹.</summary>
    public Multivector<T> Dual(Multivector<T> blade)
    {
        RequireSameFrame(this, blade, "take the dual of");
        return Lcp(InverseOfDualBlade(blade));
    }

    /// <summary>The un-dual A ⌋ I (3.66), inverse of <see cref="Dual()"/>.</summary>
    public Multivector<T> Undual() => Lcp(Pseudoscalar(Frame));

    public Multivector<T> Undual(Multivector<T> blade)
    {
        RequireSameFrame(this, blade, "take the un-dual of");
        return Lcp(blade);
    }

    private Multivector<T> InverseOfDualBlade(Multivector<T> blade)
    {
        try
        {
            return blade.Inverse();
        }
        catch (AlgebraException e) when (!e.ExceedsLimit)
        {
            throw new AlgebraException(Frame.Name,
                $"the dual needs a non-null blade, but {blade} squares to zero (a degenerate metric has no dual with respect to its pseudoscalar).");
        }
    }

    /// <summary>The versor product V A V⁻¹ (3.63) with V = this.</summary>
    public Multivector<T> Apply(Multivector<T> a)
    {
        RequireSameFrame(this, a, "apply");
        return Gp(a).Gp(Inverse());
    }

    // ---- exponential ---------------------------------------------------------------------------

    /// <summary>
    /// exp(B) for a multivector whose square is a scalar β (a 2-blade, or any bivector in 3D):
    /// cos√(−β) + B sin√(−β)/√(−β) when β &lt; 0, cosh/sinh when β &gt; 0, 1 + B when β = 0.
    /// The sign of a symbolic β comes from the metric: a 2-blade spanned by vectors of a
    /// definite sub-metric always squares to a negative number.
    /// </summary>
    public Multivector<T> Exp()
    {
        if (IsZero) return FromScalar(Frame, T.One);
        var square = Gp(this);
        var beta = square.ScalarPart;
        if (!square.Grade(0).Equals(square) && square.SelectGrades(g => g != 0).TermCount > 0)
            throw new AlgebraException(Frame.Name, $"exp is defined here for multivectors whose square is a scalar (2-blades), but {this} squares to {square}.");
        if (T.IsZero(beta)) return Add(T.One);
        var sign = T.IsNegative(beta) ? -1 : T.IsPositive(beta) ? 1 : SignFromMetric();
        if (sign < 0)
        {
            var theta = T.Sqrt(-beta);
            return FromScalar(Frame, T.Cos(theta)) + Scale(T.Sin(theta) / theta);
        }
        var phi = T.Sqrt(beta);
        return FromScalar(Frame, T.Cosh(phi)) + Scale(T.Sinh(phi) / phi);
    }

    private int SignFromMetric()
    {
        var support = 0;
        foreach (var id in Ids()) support |= id;
        var indices = new BasisBlade(support).BasisVectorIndices().ToArray();
        var sub = new Numerics.Rational[indices.Length, indices.Length];
        for (var i = 0; i < indices.Length; i++)
        for (var j = 0; j < indices.Length; j++)
            sub[i, j] = Frame.Metric[indices[i], indices[j]];
        var metric = Metric.FromMatrix(sub);
        var negated = new Numerics.Rational[indices.Length, indices.Length];
        for (var i = 0; i < indices.Length; i++)
        for (var j = 0; j < indices.Length; j++)
            negated[i, j] = -sub[i, j];
        if (metric.IsPositiveDefinite || Metric.FromMatrix(negated).IsPositiveDefinite) return -1;
        throw new AlgebraException(Frame.Name,
            $"cannot tell the sign of the square of {this} (its blades span an indefinite subspace); exp needs it to choose between trigonometric and hyperbolic forms.");
    }

    public bool Equals(Multivector<T>? other)
    {
        if (other is null || !ReferenceEquals(Frame, other.Frame) || other._ids.Length != _ids.Length) return false;
        if (_dense is not null) return DenseEquals(_dense, other._dense!);
        for (var i = 0; i < _ids.Length; i++)
            if (_ids[i] != other._ids[i] || !_coefficients[i].Equals(other._coefficients[i])) return false;
        return true;
    }
}
