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
    /// For other multivectors Ṽ/⟨VṼ⟩₀ is no inverse; a symbolic multivector whose coefficients are
    /// all constants is known at generation, so there that is an error (1 + e1: (1 + e1)(1 + e1)~ = 2 + 2e1).
    /// </summary>
    public Multivector<T> Inverse()
    {
        if (IsZero)
            throw new AlgebraException(Frame.Name, "the zero multivector has no inverse.") { NotInvertible = true };
        var reverse = Reverse();
        if (typeof(T) == typeof(Symbolic.Scalar) && Terms.All(t => ((Symbolic.Scalar)(object)t.Coefficient!).IsConstant))
        {
            var product = Gp(reverse);
            if (product.SelectGrades(g => g != 0).TermCount > 0)
                throw new AlgebraException(Frame.Name,
                    $"{this} is not a versor or blade: its product with its reverse is {product}, not a scalar, so Ã/⟨AÃ⟩₀ is not its inverse (general_inverse inverts any invertible multivector of up to 5 dimensions).");
        }
        var q = QuasiNorm();
        if (T.IsZero(q))
            throw new AlgebraException(Frame.Name, "a null versor or blade has no inverse: its quasi-norm ⟨V Ṽ⟩₀ is zero.") { NotInvertible = true };
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
                $"the dual needs a non-null blade, but the pseudoscalar of frame '{Frame.Name}' squares to zero (a degenerate metric has no dual with respect to its pseudoscalar).");
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
    /// cos θ + B sin θ/θ with θ = √(−β) when β &lt; 0, cosh/sinh when β &gt; 0, 1 + B when β = 0;
    /// for a bivector whose square also has a 4-vector part (4D, 5D), see <see cref="ExpOfBivector"/>.
    /// </summary>
    public Multivector<T> Exp() => Exp(isBlade: false);

    /// <summary>
    /// exp(B); with <paramref name="isBlade"/> the caller knows B is a blade (an outer product of
    /// vectors), so B² = ⟨BB⟩₀ even where the coefficients hide it (Plücker relations between
    /// temporaries), and only the scalar part of the square is used.
    /// <para>
    /// The sign of a symbolic β comes from its structure (a sum of squares, a square), else from the
    /// metric (a 2-blade in a definite or positive semi-definite subspace squares to ≤ 0), else the
    /// code chooses at run time. Every form is finite at β = 0 and where β underflows.
    /// </para>
    /// </summary>
    public Multivector<T> Exp(bool isBlade)
    {
        if (IsZero) return FromScalar(Frame, T.One);
        var square = Gp(this);
        var beta = square.ScalarPart;
        if (!isBlade && !square.Grade(0).Equals(square) && square.SelectGrades(g => g != 0).TermCount > 0)
        {
            if (SelectGrades(g => g != 2).IsZero) return ExpOfBivector(square);
            throw new AlgebraException(Frame.Name, $"exp is defined here for bivectors and for multivectors whose square is a scalar (blades), but this argument has {GradeList(Grades)} and its square {GradeList(square.Grades)}.");
        }
        if (T.IsZero(beta)) return Add(T.One);
        var sign = SignOf(beta) ?? SignFromMetric();
        if (sign is null) return ExpOfUnknownSign(beta);
        if (sign < 0)
        {
            var theta = T.Sqrt(-beta);
            // θ underflowed (|B| below ~1e-154): sin θ/θ and cos θ are 1 to the last bit.
            if (T.IsZero(theta)) return Add(T.One);
            var angle = Angle(-beta, theta).Value;
            return FromScalar(Frame, T.Cos(angle)) + Scale(T.Sin(angle) / angle);
        }
        var phi = T.Sqrt(beta);
        if (T.IsZero(phi)) return Add(T.One);
        var rapidity = Angle(beta, phi);
        // Without a division by the rapidity, exponentials (they combine across versor products);
        // with one, calls accurate near 0.
        var (cosh, sinh) = rapidity.Divides ? Hyperbolic(rapidity.Value) : (T.Cosh(rapidity.Value), T.Sinh(rapidity.Value));
        return FromScalar(Frame, cosh) + Scale(sinh / rapidity.Value);
    }

    /// <summary>
    /// The angle (or rapidity) √r for the generated code, chosen so that sin θ/θ (sinh θ/θ) is never
    /// 0/0. Numbers are left alone (the caller branches at 0). A symbolic θ = √(u²) = |u| is replaced
    /// by u (cos and sin θ/θ are even) when B/u has no division: then B·sin(cu)/(cu) simplifies to a
    /// product with no division at all, as in x·sin|x|/|x| = sin x. Otherwise the radicand gets
    /// 1e-40: at r = 0 (or where r underflows) the code computes sin(1e-20)/1e-20 = 1 and cos = 1;
    /// above r ≈ 1e-24 the sum rounds to r, so the code is bit-for-bit the textbook formula; in
    /// between the change is far below the last bit of results that are 1 to double precision.
    /// (1e-40 is a subnormal float, so the guard also holds in float code.)
    /// </summary>
    private (T Value, bool Divides) Angle(T radicand, T root)
    {
        if (root is not Symbolic.Scalar r) return (root, false);
        if (((Symbolic.Scalar)(object)radicand).TrySquareRoot(out var u) && DivisionFree(u)) return ((T)(object)u, false);
        if (DivisionFree(r)) return (root, false);
        return (T.Sqrt(radicand + RadicandGuard), true);
    }

    /// <summary>cosh and sinh as calls for symbolic scalars (see <see cref="Symbolic.Scalar.HyperbolicSine"/>).</summary>
    private static (T Cosh, T Sinh) Hyperbolic(T x) => x is Symbolic.Scalar s
        ? ((T)(object)Symbolic.Scalar.HyperbolicCosine(s), (T)(object)Symbolic.Scalar.HyperbolicSine(s))
        : (T.Cosh(x), T.Sinh(x));

    private bool DivisionFree(Symbolic.Scalar angle) =>
        Terms.All(t => !((Symbolic.Scalar)(object)t.Coefficient! / angle).HasDivision());

    // A double, not 10⁻⁴⁰: an exact power of ten is a square the simplifier would take out of the root.
    private static readonly T RadicandGuard = T.CreateChecked(1e-40);

    /// <summary>
    /// exp(B) when the sign of β = B² is known only at run time, without a branch:
    /// C = cosh √β₊ + cos √β₋ − 1 and S = sinh g₊/g₊ + sin g₋/g₋ − 1 with β± = (|β| ± β)/2, so one
    /// of β₊, β₋ is zero and its function contributes exactly 1; g± = √(β± + 1e-40) keep 0/0 out (see Angle).
    /// </summary>
    private Multivector<T> ExpOfUnknownSign(T beta)
    {
        var two = T.One + T.One;
        var magnitude = T.Abs(beta);
        // |…| because rounding can leave (|β| − β)/2 a hair below zero.
        var (plus, minus) = (T.Abs((magnitude + beta) / two), T.Abs((magnitude - beta) / two));
        var positive = T.Sqrt(plus);
        var negative = T.Sqrt(minus);
        var gp = T.Sqrt(plus + RadicandGuard);
        var gn = T.Sqrt(minus + RadicandGuard);
        var c = Hyperbolic(positive).Cosh + T.Cos(negative) - T.One;
        var s = Hyperbolic(gp).Sinh / gp + T.Sin(gn) / gn - T.One;
        return FromScalar(Frame, c) + Scale(s);
    }

    /// <summary>−1, 0 or +1 when the sign of <paramref name="value"/> is known for all values of its variables.</summary>
    private static int? SignOf(T value)
    {
        if (T.IsZero(value)) return 0;
        if (value is Symbolic.Scalar s) return s.KnownSign();
        return T.IsNegative(value) ? -1 : 1;
    }

    /// <summary>
    /// −1 when the blades of this multivector span a subspace whose metric is definite or positive
    /// semi-definite (a 2-blade there squares to ≤ 0: rotations, and PGA translators at 0), else null.
    /// </summary>
    private int? SignFromMetric()
    {
        var support = 0;
        foreach (var id in Ids()) support |= id;
        var indices = new BasisBlade(support).BasisVectorIndices().ToArray();
        var sub = new Numerics.Rational[indices.Length, indices.Length];
        var negated = new Numerics.Rational[indices.Length, indices.Length];
        for (var i = 0; i < indices.Length; i++)
        for (var j = 0; j < indices.Length; j++)
        {
            sub[i, j] = Frame.Metric[indices[i], indices[j]];
            negated[i, j] = -sub[i, j];
        }
        if (Metric.FromMatrix(sub).IsPositiveDefinite || Metric.FromMatrix(negated).IsPositiveDefinite || IsPositiveSemiDefinite(sub)) return -1;
        return null;
    }

    /// <summary>Every principal minor ≥ 0 (small subspaces only: a blade's support).</summary>
    private static bool IsPositiveSemiDefinite(Numerics.Rational[,] m)
    {
        var n = m.GetLength(0);
        if (n > 12) return false;
        for (var subset = 1; subset < 1 << n; subset++)
        {
            var idx = Enumerable.Range(0, n).Where(i => (subset & (1 << i)) != 0).ToArray();
            var minor = new Numerics.Rational[idx.Length, idx.Length];
            for (var i = 0; i < idx.Length; i++)
            for (var j = 0; j < idx.Length; j++)
                minor[i, j] = m[idx[i], idx[j]];
            if (new Numerics.RationalMatrix(minor).Determinant().Sign < 0) return false;
        }
        return true;
    }

    public bool Equals(Multivector<T>? other)
    {
        if (other is null || !ReferenceEquals(Frame, other.Frame) || other._ids.Length != _ids.Length) return false;
        if (_dense is not null) return DenseEquals(_dense, other._dense!);
        for (var i = 0; i < _ids.Length; i++)
            if (_ids[i] != other._ids[i] || !_coefficients[i].Equals(other._coefficients[i])) return false;
        return true;
    }

    /// <summary>"grade 2" or "grades 0, 2 and 4": a multivector described by its grades, for messages
    /// that must not print symbolic coefficients (they would show generated names, not the user's).</summary>
    internal static string GradeList(IReadOnlyList<int> grades) => grades.Count switch
    {
        0 => "no grade (it is zero)",
        1 => $"grade {grades[0]}",
        _ => $"grades {string.Join(", ", grades.Take(grades.Count - 1))} and {grades[^1]}",
    };
}
