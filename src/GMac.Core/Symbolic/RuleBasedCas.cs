using System.Runtime.CompilerServices;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

/// <summary>
/// Our own simplifier (no CAS package is available). Bottom-up over the expression it applies:
/// <list type="bullet">
/// <item>sqrt(c·m) with c a perfect square: even powers leave the root as abs(...) — so
/// sqrt(x^2) is |x| — and abs(u) becomes u or -u when interval arithmetic over the bounds fixes
/// the sign of u (sqrt(x^2) → x under x ≥ 0);</item>
/// <item>sqrt(a)^k → a^(k div 2)·sqrt(a)^(k mod 2), and abs(a)^(2k) → a^(2k);</item>
/// <item>exp(a)^p·exp(b)^q → exp(p·a + q·b); exp(log(u)) → u when u &gt; 0;</item>
/// <item>sin(u)^p·cos(u)^-q → tan(u)^min(p,q)·...;</item>
/// <item>then reduction by the side relations of the assumptions (sin^2 + cos^2 = 1, user relations).</item>
/// </list>
/// It does not factor, does not combine fractions over a common denominator and knows nothing
/// of trigonometric sum formulas. The canonical form already folds constants, cancels like
/// terms, takes odd/even signs out of sin, cos, tan, abs and maps log(exp(u)) to u.
/// </summary>
public sealed class RuleBasedCas : ICasAdapter
{
    private const int MaxRounds = 8;

    public string Name => "rules-v2";

    public Scalar Parse(string text) => Scalar.Parse(text);

    public Scalar Simplify(Scalar expression, Assumptions assumptions)
    {
        ArgumentNullException.ThrowIfNull(expression);
        ArgumentNullException.ThrowIfNull(assumptions);
        var current = assumptions.Relations.Reduce(expression);
        var pass = new Pass(assumptions, _rewrittenAtoms.GetValue(assumptions, static _ => new ConditionalWeakTable<Atom, Scalar>()));
        for (var round = 0; round < MaxRounds; round++)
        {
            var next = assumptions.Relations.Reduce(pass.Rewrite(current));
            if (ReferenceEquals(next, current)) break;
            current = next;
        }
        return current;
    }

    /// <summary>
    /// What each atom became under one set of assumptions. An atom's rewrite depends on nothing
    /// else (its arguments and the bounds), so every pass and every call with the same assumptions
    /// shares it; atoms are interned, and the table lets go of those no longer in use.
    /// </summary>
    private readonly ConditionalWeakTable<Assumptions, ConditionalWeakTable<Atom, Scalar>> _rewrittenAtoms = new();

    /// <summary>One bottom-up rewrite, memoized on atoms.</summary>
    private sealed class Pass(Assumptions assumptions, ConditionalWeakTable<Atom, Scalar> atoms)
    {
        /// <summary>
        /// Terms whose atoms all stay and that no term rule touches are kept as they are; the
        /// rest are rebuilt. When every term stays the value itself is returned, with no new sum.
        /// </summary>
        public Scalar Rewrite(Scalar value)
        {
            var terms = value.TermArray;
            ScalarSumBuilder? sum = null;
            for (var i = 0; i < terms.Length; i++)
            {
                var term = terms[i];
                var factors = term.Monomial.FactorArray;
                Scalar? product = null;
                for (var j = 0; j < factors.Length; j++)
                {
                    var image = RewriteAtom(factors[j].Atom);
                    if (product is null && ReferenceEquals(image, factors[j].Atom.AsScalar())) continue;
                    product ??= ProductOfFactors(term.Coefficient, factors, j);
                    product *= Scalar.IntegerPower(image, factors[j].Power);
                }
                if (product is null && !NeedsTermRule(factors))
                {
                    sum?.Add(term);
                    continue;
                }
                if (sum is null)
                {
                    sum = new ScalarSumBuilder();
                    for (var k = 0; k < i; k++) sum.Add(terms[k]);
                }
                foreach (var rebuilt in (product ?? Scalar.FromTerm(term.Coefficient, term.Monomial)).TermArray) sum.Add(RewriteTerm(rebuilt));
            }
            return sum is null ? value : sum.ToScalar();
        }

        /// <summary>c·f₀ᵖ⁰·…·fₖ₋₁ᵖᵏ⁻¹, the factors before index <paramref name="count"/> unchanged.</summary>
        private static Scalar ProductOfFactors(Rational coefficient, Factor[] factors, int count)
        {
            var product = Scalar.Constant(coefficient);
            for (var k = 0; k < count; k++) product *= Scalar.IntegerPower(factors[k].Atom.AsScalar(), factors[k].Power);
            return product;
        }

        private Scalar RewriteAtom(Atom atom)
        {
            if (atoms.TryGetValue(atom, out var known)) return known;
            Scalar result;
            if (atom.ArgumentArray.Length == 0) result = atom.AsScalar();
            else
            {
                var arguments = new Scalar[atom.ArgumentArray.Length];
                for (var i = 0; i < arguments.Length; i++) arguments[i] = Rewrite(atom.ArgumentArray[i]);
                result = atom.Kind switch
                {
                    AtomKind.Sqrt => SquareRoot(arguments[0]),
                    AtomKind.Abs => AbsoluteValue(arguments[0]),
                    AtomKind.Exp => Exponential(arguments[0]),
                    _ => Scalar.Apply(atom.Kind, arguments),
                };
            }
            atoms.AddOrUpdate(atom, result);
            return result;
        }

        private Scalar AbsoluteValue(Scalar u)
        {
            var bounds = assumptions.BoundsOf(u);
            if (bounds.IsNonNegative) return u;
            if (bounds.IsNonPositive) return -u;
            return Scalar.Abs(u);
        }

        private Scalar SquareRoot(Scalar u)
        {
            if (u.TermArray.Length > 1) return SquareRootOfSum(u);
            var term = u.TermArray[0];
            if (term.Coefficient.Sign < 0 || !term.Coefficient.TryExactSqrt(out var root)) return Scalar.Sqrt(u);
            // sqrt(c·Π a^p) = sqrt(c)·|Π a^(p div 2)|·sqrt(Π a^(p mod 2)), valid wherever the root is real.
            var outside = new List<Factor>();
            var inside = new List<Factor>();
            foreach (var factor in term.Monomial.FactorArray)
            {
                var half = factor.Power / 2;
                var remainder = factor.Power - 2 * half;
                if (half != 0) outside.Add(factor with { Power = half });
                if (remainder != 0) inside.Add(factor with { Power = remainder });
            }
            if (outside.Count == 0 && root.IsOne) return Scalar.Sqrt(u);
            var outer = AbsoluteValue(Scalar.FromTerm(Rational.One, Monomial.Create(outside)));
            var inner = Scalar.Sqrt(Scalar.FromTerm(Rational.One, Monomial.Create(inside)));
            return Scalar.Constant(root) * outer * inner;
        }

        /// <summary>sqrt(m²·s) = |m|·sqrt(s) for the square part m² of the monomial common to all terms.</summary>
        private Scalar SquareRootOfSum(Scalar u)
        {
            var common = new Dictionary<Atom, int>();
            var first = true;
            foreach (var term in u.TermArray)
            {
                var powers = new Dictionary<Atom, int>();
                foreach (var factor in term.Monomial.FactorArray)
                    if (factor.Power >= 2 && factor.Atom.Kind != AtomKind.Inverse) powers[factor.Atom] = factor.Power;
                if (first)
                {
                    foreach (var (atom, power) in powers) common[atom] = power;
                    first = false;
                    continue;
                }
                foreach (var atom in common.Keys.ToArray())
                    common[atom] = powers.TryGetValue(atom, out var p) ? Math.Min(common[atom], p) : 0;
            }
            var half = new List<Factor>();
            foreach (var (atom, power) in common)
                if (power >= 2) half.Add(new Factor(atom, power / 2));
            if (half.Count == 0) return Scalar.Sqrt(u);
            var m = Scalar.FromTerm(Rational.One, Monomial.Create(half));
            return AbsoluteValue(m) * Scalar.Sqrt(u / (m * m));
        }

        private Scalar Exponential(Scalar u)
        {
            if (u.TermArray.Length == 1 && u.TermArray[0].Coefficient.IsOne)
            {
                var factors = u.TermArray[0].Monomial.FactorArray;
                if (factors.Length == 1 && factors[0].Power == 1 && factors[0].Atom.Kind == AtomKind.Log)
                {
                    var argument = factors[0].Atom.ArgumentArray[0];
                    if (assumptions.BoundsOf(argument).IsPositive) return argument;
                }
            }
            return Scalar.Exp(u);
        }

        /// <summary>
        /// For a factor sin(c·|u|)ᵃ of a monomial: the atom |u|, its power b in the monomial (0 when
        /// absent) and (c, u), when a + b is even so that the signs of u cancel; else null.
        /// </summary>
        private static (Atom Atom, int Power, (Rational, Scalar) Scaled)? OddAbsolutePower(IReadOnlyList<Factor> factors, Factor sine)
        {
            if (!Scalar.TryGetScaledAtom(sine.Atom.ArgumentArray[0], AtomKind.Abs, out var c, out var abs)) return null;
            var power = 0;
            foreach (var f in factors)
                if (ReferenceEquals(f.Atom, abs)) power = f.Power;
            if ((sine.Power + power) % 2 != 0) return null;
            return (abs, power, (c, abs.ArgumentArray[0]));
        }

        /// <summary>Whether <see cref="RewriteTerm"/> would change a term with these factors.</summary>
        private static bool NeedsTermRule(Factor[] factors)
        {
            var (needed, exponentials) = TermRuleNeeds(factors);
            return needed || exponentials >= 2;
        }

        /// <summary>Whether a factor is a positive power of sin(argument).</summary>
        private static bool HasSineOf(Factor[] factors, Scalar argument)
        {
            foreach (var f in factors)
                if (f.Atom.Kind == AtomKind.Sin && f.Power > 0 && ReferenceEquals(f.Atom.ArgumentArray[0], argument)) return true;
            return false;
        }

        private static (bool Needed, int Exponentials) TermRuleNeeds(Factor[] factors)
        {
            var needed = false;
            var exponentials = 0;
            foreach (var factor in factors)
            {
                switch (factor.Atom.Kind)
                {
                    case AtomKind.Sqrt when Math.Abs(factor.Power) >= 2:
                    case AtomKind.Abs when factor.Power % 2 == 0:
                        needed = true;
                        break;
                    case AtomKind.Exp:
                        exponentials++;
                        break;
                    case AtomKind.Sin when OddAbsolutePower(factors, factor) is not null:
                        needed = true;
                        break;
                    case AtomKind.Cos when factor.Power < 0:
                        needed |= HasSineOf(factors, factor.Atom.ArgumentArray[0]);
                        break;
                }
            }
            return (needed, exponentials);
        }

        /// <summary>Rules on the factors of one monomial of the rebuilt expression.</summary>
        private static Scalar RewriteTerm(Term term)
        {
            var factors = term.Monomial.FactorArray;
            var (needed, exponentials) = TermRuleNeeds(factors);
            if (!needed && exponentials < 2) return Scalar.FromTerm(term.Coefficient, term.Monomial);

            var result = Scalar.Constant(term.Coefficient);
            var exponent = Scalar.Zero;
            var remaining = new List<Factor>(factors);
            for (var i = 0; i < remaining.Count; i++)
            {
                var factor = remaining[i];
                var atom = factor.Atom;
                if (atom.Kind == AtomKind.Sqrt && Math.Abs(factor.Power) >= 2)
                {
                    var half = factor.Power / 2;
                    result *= Scalar.IntegerPower(atom.ArgumentArray[0], half);
                    remaining[i] = factor with { Power = factor.Power - 2 * half };
                }
                else if (atom.Kind == AtomKind.Abs && factor.Power % 2 == 0)
                {
                    result *= Scalar.IntegerPower(atom.ArgumentArray[0], factor.Power);
                    remaining[i] = factor with { Power = 0 };
                }
                else if (atom.Kind == AtomKind.Exp && exponentials >= 2)
                {
                    exponent += Scalar.Scale(atom.ArgumentArray[0], factor.Power);
                    remaining[i] = factor with { Power = 0 };
                }
                else if (atom.Kind == AtomKind.Sin && OddAbsolutePower(remaining, factor) is { } absolute)
                {
                    // sin(c|u|)ᵃ·|u|ᵇ = sgn(u)ᵃ⁺ᵇ sin(cu)ᵃ·uᵇ, which is sin(cu)ᵃ·uᵇ when a + b is even.
                    var (c, u) = absolute.Scaled;
                    result *= Scalar.IntegerPower(Scalar.Sin(Scalar.Scale(u, c)), factor.Power) * Scalar.IntegerPower(u, absolute.Power);
                    remaining[i] = factor with { Power = 0 };
                    var j = remaining.FindIndex(f => ReferenceEquals(f.Atom, absolute.Atom));
                    if (j >= 0) remaining[j] = remaining[j] with { Power = 0 };
                }
                else if (atom.Kind == AtomKind.Cos && factor.Power < 0)
                {
                    var j = remaining.FindIndex(f => f.Atom.Kind == AtomKind.Sin && f.Power > 0 && ReferenceEquals(f.Atom.ArgumentArray[0], atom.ArgumentArray[0]));
                    if (j < 0) continue;
                    var k = Math.Min(remaining[j].Power, -factor.Power);
                    result *= Scalar.IntegerPower(Scalar.Tan(atom.ArgumentArray[0]), k);
                    remaining[j] = remaining[j] with { Power = remaining[j].Power - k };
                    remaining[i] = factor with { Power = factor.Power + k };
                }
            }
            if (exponentials >= 2) result *= Scalar.Exp(exponent);
            remaining.RemoveAll(f => f.Power == 0);
            return result * Scalar.FromTerm(Rational.One, Monomial.Create(remaining));
        }
    }
}
