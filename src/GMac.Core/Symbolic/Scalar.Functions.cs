using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

// Elementary functions: each folds what is exactly known and otherwise makes an atom in a
// canonical form (odd functions pull the sign of the leading term out, even ones drop it).
public sealed partial class Scalar
{
    /// <summary>Euler's number, as exp(1).</summary>
    public static Scalar E => Exp(One);

    public static Scalar Tau => Scale(Pi, 2);

    public static Scalar Sin(Scalar x)
    {
        if (x.IsStructuralZero) return Zero;
        if (TryGetPiMultiple(x, out var q))
        {
            if (q.IsInteger) return Zero;
            if ((q * 2).IsInteger) return IsOddInteger(q - new Rational(1, 2)) ? NegativeOne : One;
        }
        return LeadingCoefficientIsNegative(x) ? -Function(AtomKind.Sin, -x) : Function(AtomKind.Sin, x);
    }

    public static Scalar Cos(Scalar x)
    {
        if (x.IsStructuralZero) return One;
        // cos is even: cos(c·|u|) = cos(c·u).
        if (TryGetScaledAtom(x, AtomKind.Abs, out var c, out var abs)) return Cos(Scale(abs.ArgumentArray[0], c));
        if (TryGetPiMultiple(x, out var q))
        {
            if (q.IsInteger) return IsOddInteger(q) ? NegativeOne : One;
            if ((q * 2).IsInteger) return Zero;
        }
        return Function(AtomKind.Cos, LeadingCoefficientIsNegative(x) ? -x : x);
    }

    public static Scalar Tan(Scalar x)
    {
        if (x.IsStructuralZero) return Zero;
        if (TryGetPiMultiple(x, out var q) && q.IsInteger) return Zero;
        return LeadingCoefficientIsNegative(x) ? -Function(AtomKind.Tan, -x) : Function(AtomKind.Tan, x);
    }

    public static Scalar Sqrt(Scalar x)
    {
        if (x.TryGetConstant(out var c) && c.TryExactSqrt(out var root)) return Constant(root);
        if (PolynomialSquareRoot.TryRoot(x, out var polynomialRoot)) return Abs(polynomialRoot);
        // sqrt(k²·s) = k·sqrt(s) for a square rational content k² > 0 of all coefficients.
        var content = x.Content();
        if (!content.IsOne && content.TryExactSqrt(out var k))
            return Scale(Function(AtomKind.Sqrt, Scale(x, content.Reciprocal())), k);
        return Function(AtomKind.Sqrt, x);
    }

    /// <summary>The positive rational gcd of the coefficients (gcd of numerators over lcm of denominators).</summary>
    internal Rational Content()
    {
        if (_terms.Length == 0) return Rational.One;
        var numerator = System.Numerics.BigInteger.Zero;
        var denominator = System.Numerics.BigInteger.One;
        foreach (var term in _terms)
        {
            numerator = System.Numerics.BigInteger.GreatestCommonDivisor(numerator, term.Coefficient.Numerator);
            var d = term.Coefficient.Denominator;
            denominator = denominator / System.Numerics.BigInteger.GreatestCommonDivisor(denominator, d) * d;
        }
        return new Rational(numerator, denominator);
    }

    public static Scalar Exp(Scalar x)
    {
        if (x.IsStructuralZero) return One;
        // exp(log(u)) is u only for u > 0, so it is left to the simplifier.
        return Function(AtomKind.Exp, x);
    }

    public static Scalar Log(Scalar x)
    {
        if (x.TryGetConstant(out var c) && c.IsOne) return Zero;
        // log(exp(u)) = u holds for every real u.
        if (TryGetSingleAtom(x, AtomKind.Exp, out var exp)) return exp.ArgumentArray[0];
        return Function(AtomKind.Log, x);
    }

    public static Scalar Atan2(Scalar y, Scalar x)
    {
        if (y.TryGetConstant(out var cy) && x.TryGetConstant(out var cx))
        {
            if (cy.IsZero && cx.Sign >= 0) return Zero; // atan2(0, 0) = 0 as in Math.Atan2
            if (cy.IsZero && cx.Sign < 0) return Pi;
            if (cx.IsZero && cy.Sign != 0) return Scale(Pi, new Rational(cy.Sign, 2));
            if (cx == cy && cx.Sign != 0) return Scale(Pi, new Rational(cx.Sign > 0 ? 1 : -3, 4));
        }
        // atan2(y·a⁻ᵏ, x) = atan2(y, x·aᵏ) for a > 0: a root or absolute value dividing every term
        // of y moves over to x, so atan(n/|s|) = atan2(n/|s|, 1) reads atan2(n, |s|) with no division.
        if (CommonPositiveDenominator(y) is { } a) return Atan2(y * a, x * a);
        return Function(AtomKind.Atan2, y, x);
    }

    /// <summary>aᵏ for an atom a ≥ 0 (a square root or an absolute value) with a negative power in every term, else null.</summary>
    private static Scalar? CommonPositiveDenominator(Scalar y)
    {
        if (y._terms.Length == 0) return null;
        foreach (var factor in y._terms[0].Monomial.FactorArray)
        {
            if (factor.Power >= 0 || factor.Atom.Kind is not (AtomKind.Sqrt or AtomKind.Abs)) continue;
            var k = -factor.Power;
            foreach (var term in y._terms)
            {
                var power = 0;
                foreach (var f in term.Monomial.FactorArray)
                    if (ReferenceEquals(f.Atom, factor.Atom)) power = f.Power;
                k = Math.Min(k, -power);
            }
            if (k > 0) return FromTerm(Rational.One, Monomial.FromAtom(factor.Atom, k));
        }
        return null;
    }

    public static Scalar Abs(Scalar x)
    {
        if (x.TryGetConstant(out var c)) return Constant(c.Abs());
        if (TryGetSingleAtom(x, AtomKind.Abs, out _)) return x;
        var lead = x._terms[0].Coefficient;
        if (x._terms.Length == 1)
        {
            // |c·m| = |c|·m when every power in m is even; otherwise |c|·|m|.
            var allEven = true;
            foreach (var factor in x._terms[0].Monomial.FactorArray) allEven &= factor.Power % 2 == 0;
            if (allEven) return Scale(x, lead.Sign < 0 ? Rational.MinusOne : Rational.One);
        }
        var normalized = Scale(x, lead.Reciprocal());
        return Scale(Function(AtomKind.Abs, normalized), lead.Abs());
    }

    /// <summary>x^y: integer exponents expand, half-integer ones become powers of sqrt, others a pow atom.</summary>
    public static Scalar Pow(Scalar x, Scalar y)
    {
        if (y.TryGetConstant(out var e))
        {
            if (e.IsInteger && e.Numerator >= int.MinValue && e.Numerator <= int.MaxValue)
                return IntegerPower(x, (int)e.Numerator);
            if (e.Denominator == 2 && e.Numerator >= int.MinValue && e.Numerator <= int.MaxValue)
                return IntegerPower(Sqrt(x), (int)e.Numerator);
        }
        if (x.TryGetConstant(out var b))
        {
            if (b.IsOne) return One;
            if (b.IsZero && y.TryGetConstant(out var ey) && ey.Sign > 0) return Zero;
        }
        return Function(AtomKind.Pow, x, y);
    }

    public static Scalar Pow(Scalar x, int n) => IntegerPower(x, n);

    public static Scalar Square(Scalar x) => x * x;

    public static Scalar Cbrt(Scalar x) => RootN(x, 3);

    /// <summary>The real n-th root; odd roots of negative values are negative, as Math.Cbrt.</summary>
    public static Scalar RootN(Scalar x, int n)
    {
        if (n == 0) throw new ArgumentOutOfRangeException(nameof(n), "The zeroth root is undefined.");
        if (n == 1) return x;
        if (n == 2) return Sqrt(x);
        if (n == -1) return Reciprocal(x);
        return Pow(x, Constant(new Rational(1, n)));
    }

    public static Scalar Hypot(Scalar x, Scalar y) => Sqrt(x * x + y * y);

    public static Scalar Asin(Scalar x) => Atan2(x, Sqrt(One - x * x));
    public static Scalar Acos(Scalar x) => Atan2(Sqrt(One - x * x), x);
    public static Scalar Atan(Scalar x) => Atan2(x, One);

    public static Scalar SinPi(Scalar x) => Sin(Pi * x);
    public static Scalar CosPi(Scalar x) => Cos(Pi * x);
    public static Scalar TanPi(Scalar x) => Tan(Pi * x);
    public static Scalar AsinPi(Scalar x) => Asin(x) / Pi;
    public static Scalar AcosPi(Scalar x) => Acos(x) / Pi;
    public static Scalar AtanPi(Scalar x) => Atan(x) / Pi;
    public static Scalar Atan2Pi(Scalar y, Scalar x) => Atan2(y, x) / Pi;

    public static (Scalar Sin, Scalar Cos) SinCos(Scalar x) => (Sin(x), Cos(x));
    public static (Scalar SinPi, Scalar CosPi) SinCosPi(Scalar x) => (SinPi(x), CosPi(x));

    public static Scalar DegreesToRadians(Scalar degrees) => Scale(Pi, new Rational(1, 180)) * degrees;
    public static Scalar RadiansToDegrees(Scalar radians) => Scale(radians, 180) / Pi;

    // As exponentials, so products of versors combine (e^{θ/2}·e^{θ/2} = e^θ in a dilator).
    public static Scalar Sinh(Scalar x) => Scale(Exp(x) - Exp(-x), new Rational(1, 2));
    public static Scalar Cosh(Scalar x) => Scale(Exp(x) + Exp(-x), new Rational(1, 2));

    /// <summary>
    /// sinh as one function call (Math.Sinh in code): accurate near 0, where e^x − e^−x cancels,
    /// for code that divides by the argument (sinh φ/φ in exp of a blade).
    /// </summary>
    public static Scalar HyperbolicSine(Scalar x)
    {
        if (x.IsStructuralZero) return Zero;
        // sinh is odd: sinh(c·|u|)·… keeps its sign outside, as sin does.
        return LeadingCoefficientIsNegative(x) ? -Function(AtomKind.Sinh, -x) : Function(AtomKind.Sinh, x);
    }

    /// <summary>cosh as one function call, the partner of <see cref="HyperbolicSine"/>.</summary>
    public static Scalar HyperbolicCosine(Scalar x)
    {
        if (x.IsStructuralZero) return One;
        // cosh is even: cosh(c·|u|) = cosh(c·u).
        if (TryGetScaledAtom(x, AtomKind.Abs, out var c, out var abs)) return HyperbolicCosine(Scale(abs.ArgumentArray[0], c));
        return Function(AtomKind.Cosh, LeadingCoefficientIsNegative(x) ? -x : x);
    }
    public static Scalar Tanh(Scalar x) => (Exp(x) - Exp(-x)) / (Exp(x) + Exp(-x));
    public static Scalar Asinh(Scalar x) => Log(x + Sqrt(x * x + One));
    public static Scalar Acosh(Scalar x) => Log(x + Sqrt(x * x - One));
    public static Scalar Atanh(Scalar x) => Scale(Log((One + x) / (One - x)), new Rational(1, 2));

    public static Scalar ExpM1(Scalar x) => Exp(x) - One;
    public static Scalar Exp2(Scalar x) => Pow(Constant(2), x);
    public static Scalar Exp2M1(Scalar x) => Exp2(x) - One;
    public static Scalar Exp10(Scalar x) => Pow(Constant(10), x);
    public static Scalar Exp10M1(Scalar x) => Exp10(x) - One;

    public static Scalar Log(Scalar x, Scalar newBase) => Log(x) / Log(newBase);
    public static Scalar Log2(Scalar x) => Log(x) / Log(Constant(2));
    public static Scalar Log10(Scalar x) => Log(x) / Log(Constant(10));
    public static Scalar LogP1(Scalar x) => Log(x + One);
    public static Scalar Log2P1(Scalar x) => Log2(x + One);
    public static Scalar Log10P1(Scalar x) => Log10(x + One);

    private static Scalar Function(AtomKind kind, params Scalar[] arguments) =>
        Atom.Create(kind, FunctionName(kind), arguments).AsScalar();

    internal static string FunctionName(AtomKind kind) => kind switch
    {
        AtomKind.Sin => "sin",
        AtomKind.Cos => "cos",
        AtomKind.Tan => "tan",
        AtomKind.Sqrt => "sqrt",
        AtomKind.Exp => "exp",
        AtomKind.Log => "log",
        AtomKind.Atan2 => "atan2",
        AtomKind.Abs => "abs",
        AtomKind.Pow => "pow",
        AtomKind.Inverse => "inv",
        AtomKind.Pi => "pi",
        AtomKind.Sinh => "sinh",
        AtomKind.Cosh => "cosh",
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Variables have no function name."),
    };

    /// <summary>Rebuilds a function atom of the given kind from (possibly new) arguments, folding again.</summary>
    internal static Scalar Apply(AtomKind kind, Scalar[] arguments) => kind switch
    {
        AtomKind.Sin => Sin(arguments[0]),
        AtomKind.Cos => Cos(arguments[0]),
        AtomKind.Tan => Tan(arguments[0]),
        AtomKind.Sqrt => Sqrt(arguments[0]),
        AtomKind.Exp => Exp(arguments[0]),
        AtomKind.Log => Log(arguments[0]),
        AtomKind.Atan2 => Atan2(arguments[0], arguments[1]),
        AtomKind.Abs => Abs(arguments[0]),
        AtomKind.Pow => Pow(arguments[0], arguments[1]),
        AtomKind.Inverse => Reciprocal(arguments[0]),
        AtomKind.Pi => Pi,
        AtomKind.Sinh => HyperbolicSine(arguments[0]),
        AtomKind.Cosh => HyperbolicCosine(arguments[0]),
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Variables are not functions."),
    };

    private bool IsStructuralZero => _terms.Length == 0;

    private static bool IsOddInteger(Rational q) => q.IsInteger && !q.Numerator.IsEven;

    private static bool LeadingCoefficientIsNegative(Scalar x) => x._terms.Length > 0 && x._terms[0].Coefficient.Sign < 0;

    private static bool TryGetPiMultiple(Scalar x, out Rational multiple)
    {
        multiple = Rational.Zero;
        if (x._terms.Length != 1) return false;
        var factors = x._terms[0].Monomial.FactorArray;
        if (factors.Length != 1 || factors[0].Atom.Kind != AtomKind.Pi || factors[0].Power != 1) return false;
        multiple = x._terms[0].Coefficient;
        return true;
    }

    /// <summary>x = c·a for a rational c and a single atom a of the given kind.</summary>
    internal static bool TryGetScaledAtom(Scalar x, AtomKind kind, out Rational coefficient, out Atom atom)
    {
        atom = null!;
        coefficient = Rational.Zero;
        if (x._terms.Length != 1) return false;
        var factors = x._terms[0].Monomial.FactorArray;
        if (factors.Length != 1 || factors[0].Power != 1 || factors[0].Atom.Kind != kind) return false;
        atom = factors[0].Atom;
        coefficient = x._terms[0].Coefficient;
        return true;
    }

    private static bool TryGetSingleAtom(Scalar x, AtomKind kind, out Atom atom)
    {
        atom = null!;
        if (x._terms.Length != 1 || !x._terms[0].Coefficient.IsOne) return false;
        var factors = x._terms[0].Monomial.FactorArray;
        if (factors.Length != 1 || factors[0].Power != 1 || factors[0].Atom.Kind != kind) return false;
        atom = factors[0].Atom;
        return true;
    }
}
