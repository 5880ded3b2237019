namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    // ---- exp of a general bivector (4D, 5D) --------------------------------------------------------

    /// <summary>
    /// exp(B) for a bivector whose square β = s + W has a 4-vector part (B is no blade: a 4D rotation
    /// in two planes, a PGA screw motion, a conformal loxodromic motion). With C(x) = Σ xʲ/(2j)! and
    /// S(x) = Σ xʲ/(2j+1)! (cosh √x and sinh √x/√x; cos and sin for x &lt; 0), exp(B) = C(β) + B·S(β),
    /// both evaluated in the algebra of 1 and W (see <see cref="OnSplitPair"/>).
    /// <para>
    /// When the blades of B span a definite or positive semi-definite subspace (Euclidean, PGA, a
    /// conformal motor without no), every simple part squares to ≤ 0 and ω = W² ≥ 0: only cos and
    /// sin appear. Otherwise signs known from structure are used, and the rest is chosen at run time
    /// without a branch.
    /// </para>
    /// </summary>
    private Multivector<T> ExpOfBivector(Multivector<T> square)
    {
        var (w, omega) = FourVectorPart(square, "exp");
        var s = square.ScalarPart;
        var rotations = SignFromMetric() == -1;
        var omegaSign = rotations ? 1 : SignOf(omega);
        PairValue c, sc;
        if (omegaSign is >= 0)
        {
            c = OnSplitPair(s, w, omega, x => CoshSinc(x, rotations).C, x => CoshSinc(x, rotations).S / (T.One + T.One));
            sc = OnSplitPair(s, w, omega, x => CoshSinc(x, rotations).S, x => SincDerivative(x, rotations));
        }
        else if (omegaSign < 0)
            (c, sc) = OnComplexPair(s, w, omega);
        else
        {
            // ω of unknown sign: the split form at ω₊ = max(ω, 0) plus the complex form at
            // ω₋ = max(−ω, 0), less the value both give at 0 (f(s) + f′(s)W).
            var two = T.One + T.One;
            var magnitude = T.Abs(omega);
            var (plus, minus) = (T.Abs((magnitude + omega) / two), T.Abs((magnitude - omega) / two));
            var split = (C: OnSplitPair(s, w, plus, x => CoshSinc(x, false).C, x => CoshSinc(x, false).S / two),
                         S: OnSplitPair(s, w, plus, x => CoshSinc(x, false).S, x => SincDerivative(x, false)));
            var complex = OnComplexPair(s, w, -minus);
            var (c0, s0) = CoshSinc(s, false);
            var s1 = SincDerivative(s, false);
            c = split.C + complex.C + new PairValue(-c0, -(s0 / two), w);
            sc = split.S + complex.S + new PairValue(-s0, -s1, w);
        }
        return c.AsMultivector(Frame) + sc.LeftTimes(this, m => m.Grade(2));
    }

    /// <summary>
    /// C(x) and S(x) for a real x: cos √−x and sin √−x/√−x when <paramref name="rotation"/> says x ≤ 0
    /// (|x| absorbs rounding above 0), the sign structure shows otherwise, and without a branch when
    /// it is unknown. Radicands carry 1e-40, so S(0) is sin(1e-20)/1e-20 = 1.
    /// </summary>
    private static (T C, T S) CoshSinc(T x, bool rotation)
    {
        var sign = rotation ? -1 : SignOf(x);
        if (sign is < 0)
        {
            var theta = T.Sqrt((rotation ? T.Abs(x) : -x) + Guard);
            return (T.Cos(theta), T.Sin(theta) / theta);
        }
        if (sign is > 0)
        {
            var phi = T.Sqrt(x + Guard);
            var (ch, sh) = Hyperbolic(phi);
            return (ch, sh / phi);
        }
        var two = T.One + T.One;
        var magnitude = T.Abs(x);
        var (plus, minus) = (T.Abs((magnitude + x) / two), T.Abs((magnitude - x) / two));
        var (gp, gn) = (T.Sqrt(plus + Guard), T.Sqrt(minus + Guard));
        var (cosh, sinh) = Hyperbolic(gp);
        return (cosh + T.Cos(gn) - T.One, sinh / gp + T.Sin(gn) / gn - T.One);
    }

    /// <summary>
    /// S′(x) = (C(x) − S(x))/(2x), 1/6 at 0: x(C − S)/(2x² + g) + (g/6)/(2x² + g) is that quotient
    /// when x² ≫ g = 1e-30 and 1/6 at x = 0.
    /// </summary>
    private static T SincDerivative(T x, bool rotation)
    {
        var (c, s) = CoshSinc(x, rotation);
        var two = T.One + T.One;
        var denominator = two * x * x + Blend;
        return (x * (c - s) + Blend / T.CreateChecked(6)) / denominator;
    }

    /// <summary>
    /// C(β) and S(β) for β = s + W with W² = ω &lt; 0: C and S at the complex number s + iq, q = √−ω,
    /// whose imaginary parts over q need no q: with √(s + iq) = a + ib (q = 2ab, a² + b² = m = |s + iq|),
    /// Im C/q = ½·(sinh a/a)(sin b/b) and Im S/q = (cosh a·sin b/b − cos b·sinh a/a)/(2m), 1/6 at m = 0.
    /// </summary>
    private static (PairValue C, PairValue S) OnComplexPair(T s, Multivector<T> w, T omega)
    {
        var two = T.One + T.One;
        var m = T.Sqrt(s * s - omega);
        var (a2, b2) = (T.Abs((m + s) / two), T.Abs((m - s) / two));
        var (a, b) = (T.Sqrt(a2), T.Sqrt(b2));
        var (ag, bg) = (T.Sqrt(a2 + Guard), T.Sqrt(b2 + Guard));
        var (ch, sh) = Hyperbolic(a);
        var (cb, sb) = (T.Cos(b), T.Sin(b));
        var shc = Hyperbolic(ag).Sinh / ag;
        var sbc = T.Sin(bg) / bg;
        // sinh(a + ib)/(a + ib); at m = 0 the real part is g/g = 1.
        var reS = (a * sh * cb + b * ch * sb + Blend) / (m + Blend);
        var imS = (ch * sbc - cb * shc + Blend / T.CreateChecked(6)) / (two * m + Blend);
        return (new PairValue(ch * cb, shc * sbc / two, w), new PairValue(reS, imS, w));
    }
}
