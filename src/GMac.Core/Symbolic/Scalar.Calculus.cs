using System.Buffers;
using GMac.Core.Numerics;

namespace GMac.Core.Symbolic;

// Evaluation, substitution and differentiation: all walk the canonical structure and memoize
// per call on atoms, since shared subexpressions are shared objects.
public sealed partial class Scalar
{
    public double Evaluate(IReadOnlyDictionary<string, double> values)
    {
        ArgumentNullException.ThrowIfNull(values);
        return Evaluate(name => values.TryGetValue(name, out var v)
            ? v
            : throw new KeyNotFoundException($"No value was given for the variable '{name}'."));
    }

    public double Evaluate(Func<string, double> valueOf)
    {
        ArgumentNullException.ThrowIfNull(valueOf);
        return Evaluate(this, valueOf, new Dictionary<Atom, double>());
    }

    private static double Evaluate(Scalar s, Func<string, double> valueOf, Dictionary<Atom, double> memo)
    {
        var sum = 0.0;
        foreach (var term in s._terms)
        {
            var product = term.Coefficient.ToDouble();
            foreach (var factor in term.Monomial.FactorArray)
                product *= IntegerPowerOf(EvaluateAtom(factor.Atom, valueOf, memo), factor.Power);
            sum += product;
        }
        return sum;
    }

    private static double IntegerPowerOf(double x, int n)
    {
        if (n == 1) return x;
        if (n == 2) return x * x;
        if (n < 0) return 1.0 / IntegerPowerOf(x, -n);
        var result = 1.0;
        while (n > 0)
        {
            if ((n & 1) != 0) result *= x;
            x *= x;
            n >>= 1;
        }
        return result;
    }

    private static double EvaluateAtom(Atom atom, Func<string, double> valueOf, Dictionary<Atom, double> memo)
    {
        if (memo.TryGetValue(atom, out var known)) return known;
        var a = atom.ArgumentArray;
        var value = atom.Kind switch
        {
            AtomKind.Variable => valueOf(atom.Name),
            AtomKind.Pi => Math.PI,
            AtomKind.Sin => Math.Sin(Evaluate(a[0], valueOf, memo)),
            AtomKind.Cos => Math.Cos(Evaluate(a[0], valueOf, memo)),
            AtomKind.Tan => Math.Tan(Evaluate(a[0], valueOf, memo)),
            AtomKind.Sqrt => Math.Sqrt(Evaluate(a[0], valueOf, memo)),
            AtomKind.Exp => Math.Exp(Evaluate(a[0], valueOf, memo)),
            AtomKind.Log => Math.Log(Evaluate(a[0], valueOf, memo)),
            AtomKind.Atan2 => Math.Atan2(Evaluate(a[0], valueOf, memo), Evaluate(a[1], valueOf, memo)),
            AtomKind.Abs => Math.Abs(Evaluate(a[0], valueOf, memo)),
            AtomKind.Pow => RealPower(Evaluate(a[0], valueOf, memo), a[1], Evaluate(a[1], valueOf, memo)),
            AtomKind.Inverse => 1.0 / Evaluate(a[0], valueOf, memo),
            AtomKind.Sinh => Math.Sinh(Evaluate(a[0], valueOf, memo)),
            AtomKind.Cosh => Math.Cosh(Evaluate(a[0], valueOf, memo)),
            _ => throw new InvalidOperationException($"Unknown atom kind {atom.Kind}."),
        };
        memo[atom] = value;
        return value;
    }

    /// <summary>Math.Pow, except that a negative base under a constant exponent p/q with odd q has the real root.</summary>
    private static double RealPower(double x, Scalar exponent, double y)
    {
        if (x < 0 && exponent.TryGetConstant(out var e) && !e.Denominator.IsEven)
        {
            var magnitude = Math.Pow(-x, y);
            return e.Numerator.IsEven ? magnitude : -magnitude;
        }
        return Math.Pow(x, y);
    }

    /// <summary>Replaces variables by scalars everywhere (arguments included) and re-canonicalizes.</summary>
    public Scalar Substitute(IReadOnlyDictionary<string, Scalar> replacements)
    {
        ArgumentNullException.ThrowIfNull(replacements);
        if (replacements.Count == 0 || !ReadsAny(this, replacements)) return this;
        // A function atom whose arguments read none of the variables stays as it is: saying so up
        // front saves walking its arguments (often large shared sums such as a denominator).
        return MapAtoms(this, atom => atom.Kind == AtomKind.Variable
                ? replacements.TryGetValue(atom.Name, out var r) ? r : null
                : atom.ArgumentArray.Length > 0 && !Array.Exists(atom.ArgumentArray, a => ReadsAny(a, replacements)) ? atom.AsScalar() : null,
            new Dictionary<Atom, Scalar>());
    }

    private static bool ReadsAny(Scalar s, IReadOnlyDictionary<string, Scalar> replacements)
    {
        var variables = s.Variables;
        if (variables.Count < replacements.Count)
        {
            foreach (var name in variables)
                if (replacements.ContainsKey(name)) return true;
            return false;
        }
        foreach (var name in replacements.Keys)
            if (variables.Contains(name)) return true;
        return false;
    }

    public Scalar Substitute(string variable, Scalar replacement) =>
        Substitute(new Dictionary<string, Scalar> { [variable] = replacement });

    /// <summary>
    /// Rebuilds a scalar bottom-up: <paramref name="rewrite"/> may replace an atom (null keeps it,
    /// after its arguments have been rebuilt and the function folded again). Atoms with arguments
    /// are remembered in <paramref name="memo"/>; for the others (variables, constants) the rewrite
    /// is asked again each time, so it must be cheap for them.
    /// </summary>
    internal static Scalar MapAtoms(Scalar s, Func<Atom, Scalar?> rewrite, Dictionary<Atom, Scalar> memo)
    {
        if (s._terms.Length == 0) return s;
        var width = 0;
        foreach (var term in s._terms) width += term.Monomial.FactorArray.Length;
        // the image of every factor, row after row; rented, since most calls change nothing
        var images = ArrayPool<Scalar>.Shared.Rent(width);
        try
        {
            var changed = false;
            var k = 0;
            foreach (var term in s._terms)
            {
                foreach (var factor in term.Monomial.FactorArray)
                {
                    var image = MapAtom(factor.Atom, rewrite, memo);
                    changed |= !ReferenceEquals(image, factor.Atom.AsScalar());
                    images[k++] = image;
                }
            }
            if (!changed) return s;
            var sum = new ScalarSumBuilder();
            k = 0;
            foreach (var term in s._terms)
            {
                var product = Constant(term.Coefficient);
                foreach (var factor in term.Monomial.FactorArray) product *= IntegerPower(images[k++], factor.Power);
                sum.Add(product);
            }
            return sum.ToScalar();
        }
        finally
        {
            ArrayPool<Scalar>.Shared.Return(images, clearArray: true);
        }
    }

    private static Scalar MapAtom(Atom atom, Func<Atom, Scalar?> rewrite, Dictionary<Atom, Scalar> memo)
    {
        var arguments = atom.ArgumentArray;
        if (arguments.Length == 0) return rewrite(atom) ?? atom.AsScalar();
        if (memo.TryGetValue(atom, out var known)) return known;
        Scalar result;
        var direct = rewrite(atom);
        if (direct is not null) result = direct;
        else
        {
            var mapped = new Scalar[arguments.Length];
            var changed = false;
            for (var i = 0; i < arguments.Length; i++)
            {
                mapped[i] = MapAtoms(arguments[i], rewrite, memo);
                changed |= !ReferenceEquals(mapped[i], arguments[i]);
            }
            result = changed ? Apply(atom.Kind, mapped) : atom.AsScalar();
        }
        memo[atom] = result;
        return result;
    }

    /// <summary>The partial derivative with respect to a variable (chain rule through every atom kind).</summary>
    public Scalar Derivative(string variable)
    {
        ArgumentNullException.ThrowIfNull(variable);
        return Derivative(this, variable, new Dictionary<Atom, Scalar>());
    }

    private static Scalar Derivative(Scalar s, string variable, Dictionary<Atom, Scalar> memo)
    {
        if (!s.Variables.Contains(variable)) return Zero;
        var sum = Zero;
        foreach (var term in s._terms)
        {
            var factors = term.Monomial.FactorArray;
            for (var i = 0; i < factors.Length; i++)
            {
                var inner = AtomDerivative(factors[i].Atom, variable, memo);
                if (inner.IsStructuralZero) continue;
                // d(a^p) = p a^(p-1) da, times the other factors unchanged.
                var power = factors[i].Power;
                var others = FromTerm(term.Coefficient * power, Monomial.WithPower(term.Monomial, factors[i].Atom, 0));
                sum += others * IntegerPower(factors[i].Atom.AsScalar(), power - 1) * inner;
            }
        }
        return sum;
    }

    private static Scalar AtomDerivative(Atom atom, string variable, Dictionary<Atom, Scalar> memo)
    {
        // variables and constants are answered directly; only functions are worth remembering
        if (atom.Kind == AtomKind.Variable) return atom.Name == variable ? One : Zero;
        var a = atom.ArgumentArray;
        if (!ReadsVariable(a, variable)) return Zero;
        if (memo.TryGetValue(atom, out var known)) return known;
        var self = atom.AsScalar();
        Scalar result;
        switch (atom.Kind)
        {
            case AtomKind.Atan2:
            {
                // d atan2(y, x) = (x dy - y dx) / (x² + y²)
                var dy = Derivative(a[0], variable, memo);
                var dx = Derivative(a[1], variable, memo);
                result = (a[1] * dy - a[0] * dx) / (a[1] * a[1] + a[0] * a[0]);
                break;
            }
            case AtomKind.Pow:
            {
                // d x^y = x^y (y' log x + y x'/x)
                var dx = Derivative(a[0], variable, memo);
                var dy = Derivative(a[1], variable, memo);
                result = self * ((dy.IsStructuralZero ? Zero : dy * Log(a[0])) + a[1] * dx / a[0]);
                break;
            }
            default:
            {
                var du = Derivative(a[0], variable, memo);
                result = du.IsStructuralZero ? Zero : du * (atom.Kind switch
                {
                    AtomKind.Sin => Cos(a[0]),
                    AtomKind.Cos => -Sin(a[0]),
                    AtomKind.Tan => One + self * self,
                    AtomKind.Sqrt => Scale(Reciprocal(self), new Rational(1, 2)),
                    AtomKind.Exp => self,
                    AtomKind.Log => Reciprocal(a[0]),
                    AtomKind.Abs => a[0] * Reciprocal(self),
                    AtomKind.Inverse => -(self * self),
                    AtomKind.Sinh => HyperbolicCosine(a[0]),
                    AtomKind.Cosh => HyperbolicSine(a[0]),
                    _ => throw new InvalidOperationException($"Unknown atom kind {atom.Kind}."),
                });
                break;
            }
        }
        memo[atom] = result;
        return result;
    }

    private static bool ReadsVariable(Scalar[] arguments, string variable)
    {
        foreach (var argument in arguments)
            if (argument.Variables.Contains(variable)) return true;
        return false;
    }
}
