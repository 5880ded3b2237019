namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    // ---- functions on x + W, W a 4-vector whose square is a scalar -----------------------------------
    //
    // A bivector B of a 4D or 5D frame squares to β = s + W (a scalar and a 4-vector), and W = B∧B is
    // a 4-blade there, so W² = ω is a scalar. 1 and W span a commutative algebra in which β lives and
    // which commutes with B; a power series f evaluated at β is f_even + f_odd·W with
    //   ω > 0, r = √ω:  f_even = (f(s + r) + f(s − r))/2,  f_odd = (f(s + r) − f(s − r))/(2r)
    //   ω = 0:          f_even = f(s),                      f_odd = f′(s)
    //   ω < 0, q = √−ω: f_even = Re f(s + iq),              f_odd = Im f(s + iq)/q
    // (split, dual and complex numbers). This is the invariant decomposition of Roelfs and De Keninck
    // written without splitting B: the eigenvalues s ± r are the squares of the commuting simple parts
    // when both are real.

    /// <summary>1e-40 (a subnormal float) added to radicands: keeps 0/0 out of the generated code; see <see cref="Angle"/>.</summary>
    private static T Guard => RadicandGuard;

    /// <summary>
    /// 1e-30 added to denominators that vanish at zero, (p + g·limit)/(q + g): the simplifier scales
    /// such a quotient to a denominator 1 + q/g, so g must keep 1/g within float range. Where q is
    /// below g the quotient blends towards its limit, which it equals there to rounding.
    /// </summary>
    private static readonly T Blend = T.CreateChecked(1e-30);

    /// <summary>
    /// f(x + W) = Even + Σ coefficient·direction, the directions W or W/u. Kept apart so that a
    /// product with the directions (B·W, a polynomial) is formed before the transcendental
    /// coefficients multiply it: symbolic expressions stay small.
    /// </summary>
    private readonly record struct PairValue(T Even, (T Coefficient, Multivector<T> Direction)[] Odd)
    {
        public PairValue(T even, T coefficient, Multivector<T> direction) : this(even, [(coefficient, direction)]) { }

        /// <summary>Even·<paramref name="left"/> + Σ coefficient·(left·direction), the product of left and this value.</summary>
        public Multivector<T> LeftTimes(Multivector<T> left, Func<Multivector<T>, Multivector<T>> project)
        {
            var sum = left.Scale(Even);
            foreach (var (coefficient, direction) in Odd)
                if (!direction.IsZero) sum += project(left.Gp(direction)).Scale(coefficient);
            return sum;
        }

        public Multivector<T> AsMultivector(Frame frame) => LeftTimes(Multivector<T>.FromScalar(frame, T.One), m => m);

        public static PairValue operator +(PairValue a, PairValue b) => new(a.Even + b.Even, [.. a.Odd, .. b.Odd]);
    }

    /// <summary>
    /// f_odd·W for ω ≥ 0 from (f(s + r) − f(s − r))/2 and f′(s) without a division by zero:
    /// (h·r + f′(s)·g)/(ω + g) is f_odd when ω ≫ g = 1e-30 and f′(s) at ω = 0; a symbolic ω that is
    /// a square u² with W/u free of divisions gives h·(W/u) instead, exactly.
    /// </summary>
    private static (T Coefficient, Multivector<T> Direction) OddPart(Multivector<T> w, T omega, T r, T halfDifference, Func<T> derivative)
    {
        if (omega is Symbolic.Scalar o && o.TrySquareRoot(out var u) && !Symbolic.Scalar.IsZero(u) && DivideExactly(w, u) is { } unit)
        {
            // r was computed from the same root, so (f(s + r) − f(s − r))/2 pairs with W/u.
            return (halfDifference, unit);
        }
        return ((halfDifference * r + derivative() * Blend) / (omega + Blend), w);
    }

    /// <summary>
    /// W/u when every coefficient of W divides by the polynomial u without a remainder (a
    /// monomial quotient, or a constant multiple of u), else null.
    /// </summary>
    private static Multivector<T>? DivideExactly(Multivector<T> w, Symbolic.Scalar u)
    {
        var terms = new List<(BasisBlade, T)>();
        foreach (var (blade, coefficient) in w.Terms)
        {
            var c = (Symbolic.Scalar)(object)coefficient!;
            var quotient = c / u;
            if (quotient.HasDivision())
            {
                if (c.Terms.Count != u.Terms.Count || c.Terms[0].Monomial != u.Terms[0].Monomial) return null;
                var k = Symbolic.Scalar.Constant(c.Terms[0].Coefficient / u.Terms[0].Coefficient);
                if (!Symbolic.Scalar.IsZero(c - k * u)) return null;
                quotient = k;
            }
            terms.Add((blade, (T)(object)quotient));
        }
        return FromTerms(w.Frame, terms);
    }

    /// <summary>The square root used for ω in <see cref="OddPart"/>: the exact root of a symbolic square.</summary>
    private static T RootOf(T omega)
    {
        if (omega is Symbolic.Scalar o && o.TrySquareRoot(out var u) && !Symbolic.Scalar.IsZero(u)) return (T)(object)u;
        return T.Sqrt(omega);
    }

    /// <summary>atan2 in either scalar domain.</summary>
    private static T Atan2(T y, T x) => (y, x) switch
    {
        (Symbolic.Scalar sy, Symbolic.Scalar sx) => (T)(object)Symbolic.Scalar.Atan2(sy, sx),
        (double dy, double dx) => (T)(object)Math.Atan2(dy, dx),
        (float fy, float fx) => (T)(object)MathF.Atan2(fy, fx),
        _ => throw new NotSupportedException($"atan2 of {typeof(T).Name}"),
    };

    /// <summary>
    /// The 4-vector part of a square that must be a scalar plus a 4-vector whose own square is a
    /// scalar (ω), or an error naming what was squared.
    /// </summary>
    private (Multivector<T> W, T Omega) FourVectorPart(Multivector<T> square, string what)
    {
        var w = square.Grade(4);
        if (!Negligible(square.SelectGrades(g => g is not (0 or 4)), square))
            throw new AlgebraException(Frame.Name,
                $"{what} needs an argument whose square has grades 0 and 4 only (frames up to 5D), but its square has {GradeList(square.Grades)}.");
        if (w.IsZero) return (w, T.Zero);
        var ww = w.Gp(w);
        if (!Negligible(ww.SelectGrades(g => g != 0), ww))
            throw new AlgebraException(Frame.Name,
                $"{what} needs the 4-vector part of its argument's square to be a blade (a 4D or 5D frame), but that part squares to {GradeList(ww.Grades)}.");
        return (w, ww.ScalarPart);
    }

    /// <summary>
    /// Zero for symbolic scalars; for numbers, rounding of a sum that cancels (below 1e-12 of the
    /// whole) is taken as zero too.
    /// </summary>
    private static bool Negligible(Multivector<T> rest, Multivector<T> whole)
    {
        if (rest.IsZero) return true;
        if (typeof(T) == typeof(Symbolic.Scalar)) return false;
        static double Size(Multivector<T> m) => m.Terms.Sum(t => Math.Abs(double.CreateChecked(t.Coefficient)));
        return Size(rest) <= 1e-12 * Size(whole);
    }

    /// <summary>
    /// f(x + W) for W² = ω known to be ≥ 0 (split or dual). The caller's f and f′ are real functions
    /// on the real line (their arguments x ± √ω).
    /// </summary>
    private static PairValue OnSplitPair(T x, Multivector<T> w, T omega, Func<T, T> f, Func<T, T> derivative)
    {
        if (w.IsZero) return new PairValue(f(x), []);
        if (T.IsZero(omega)) return new PairValue(f(x), derivative(x), w);
        var r = RootOf(omega);
        var (plus, minus) = (f(x + r), f(x - r));
        var two = T.One + T.One;
        var (coefficient, direction) = OddPart(w, omega, r, (plus - minus) / two, () => derivative(x));
        return new PairValue((plus + minus) / two, coefficient, direction);
    }
}
