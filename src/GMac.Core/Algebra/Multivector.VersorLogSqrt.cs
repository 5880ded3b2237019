namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    // ---- logarithm and square root of rotors and motors ----------------------------------------------

    /// <summary>
    /// log M of a normalized rotor or motor (M M̃ = 1, grades 0, 2 and 4), the bivector B with
    /// exp(B) = M and angles θ = |B| in [0, π): with c = ⟨M⟩₀ + ⟨M⟩₄, B = ⟨M⟩₂·L(c) where
    /// L(c) = acos c/√(1 − c²) = θ/sin θ, evaluated in the algebra of 1 and ⟨M⟩₄ (dual for PGA and
    /// conformal motors, split for 4D rotations in two planes).
    /// <para>
    /// Defined where the planes of M square to ≤ 0: the blades span a definite or positive
    /// semi-definite subspace (Euclidean, PGA, conformal rotations and translations), or the scalar
    /// part of ⟨M⟩₂² is ≤ 0 by structure. Finite everywhere: L = 1 at the identity (1e-40 in the
    /// radicands); at M = −1 exactly (θ = π, any plane) the result is 0.
    /// </para>
    /// </summary>
    public Multivector<T> Log()
    {
        if (SelectGrades(g => g is not (0 or 2 or 4)).TermCount > 0)
            throw new AlgebraException(Frame.Name, $"log is defined here for rotors and motors (grades 0, 2 and 4), not for {this}.");
        var m2 = Grade(2);
        var u = Grade(4);
        var c0 = ScalarPart;
        var sigma = m2.Gp(m2).ScalarPart;
        var structural = SignOf(-sigma) is >= 0;
        if (!structural && SignFromMetric() != -1)
            throw new AlgebraException(Frame.Name,
                $"log is defined here for rotors and motors whose planes square to ≤ 0 (rotations, translations), but the blades of {this} span an indefinite subspace.");
        if (m2.IsZero) return m2;
        var (w, omega) = u.IsZero ? (u, T.Zero) : FourVectorPart(FromScalar(Frame, c0) + u, "log");
        if (w.IsZero || T.IsZero(omega))
        {
            // sin²θ from ⟨M⟩₂² (accurate near the identity, where 1 − c² cancels).
            var n2 = structural ? -sigma : T.Abs(sigma);
            var (l, derivative) = LogFactor(c0, n2);
            var result = m2.Scale(l);
            return w.IsZero ? result : result + m2.Gp(w).Grade(2).Scale(derivative);
        }
        if (SignOf(omega) is not > 0 && SignFromMetric() != -1)
            throw new AlgebraException(Frame.Name, "log is defined here for rotors and motors; the square of the argument's 4-vector part is not known to be ≥ 0 (a boost, dilator or loxodrome).");
        return OnSplitPair(c0, w, omega, x => LogFactor(x, T.Abs(T.One - x * x)).Value, x => LogFactor(x, T.Abs(T.One - x * x)).Derivative)
            .LeftTimes(m2, m => m.Grade(2));
    }

    /// <summary>
    /// L(c) = θ/sin θ with θ = atan2(sin θ, c) and sin²θ = <paramref name="n2"/>, and L′(c) = (cL − 1)/sin²θ
    /// (−1/3 at the identity): guarded (1e-40 in the root, 1e-30 in the quotient) so that they are 1
    /// and −1/3 there, not 0/0.
    /// </summary>
    private static (T Value, T Derivative) LogFactor(T c, T n2)
    {
        var n = T.Sqrt(n2 + Guard);
        var value = Atan2(n, c) / n;
        return (value, (c * value - T.One - Blend / T.CreateChecked(3)) / (n2 + Blend));
    }

    /// <summary>
    /// √R of a normalized rotor or motor R (R R̃ = 1, ⟨R⟩₀ &gt; −1): N = 1 + R is a versor of half the
    /// angle (and half the translation), so √R = N (N Ñ)^(−1/2) with N Ñ = 2 + R + R̃ = x + V, V a
    /// 4-vector: N/√x in 3D, N/√x·(1 − V/(2x)) for PGA and conformal motors (V² = 0), and both
    /// square roots of x ± √(V²) for 4D rotations in two planes. Undefined at R = −1 (x = 0).
    /// </summary>
    public Multivector<T> VersorSqrt()
    {
        if (SelectGrades(g => g % 2 != 0).TermCount > 0)
            throw new AlgebraException(Frame.Name, $"sqrt is defined here for rotors and motors (even grades), not for {this}.");
        var n = Add(T.One);
        var nn = n.Gp(n.Reverse());
        var x = nn.ScalarPart;
        if (Negligible(nn.SelectGrades(g => g != 0), nn)) return n / T.Sqrt(x);
        var (w, omega) = FourVectorPart(nn, "sqrt");
        if (SignOf(omega) is not >= 0 && SignFromMetric() != -1)
            throw new AlgebraException(Frame.Name, $"sqrt is defined here for rotors and motors; (1 + R)(1 + R)~ of {this} has a 4-vector part whose square is not known to be ≥ 0.");
        var two = T.One + T.One;
        return OnSplitPair(x, w, omega, t => T.One / T.Sqrt(t), t => -T.One / (two * t * T.Sqrt(t))).LeftTimes(n, m => m);
    }
}
