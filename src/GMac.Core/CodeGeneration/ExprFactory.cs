using GMac.Core.Numerics;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Builds expression nodes in a normal shape: nested sums and products flattened, constants
/// folded, unit factors and zero terms dropped, negations pulled to the front of products.
/// Every pass builds through here, so trees stay comparable.
/// </summary>
public static class ExprFactory
{
    public static Expr Constant(double value) => new ConstantExpr(value);
    public static Expr Constant(Rational value) => ConstantExpr.From(value);
    public static Expr Constant(int value) => ConstantExpr.From(value);
    public static Expr Variable(string name) => new VariableExpr(name);

    public static Expr Negate(Expr e) => e switch
    {
        NegateExpr n => n.Operand,
        ConstantExpr c => c.Exact is { } r ? ConstantExpr.From(-r) : new ConstantExpr(-c.Value),
        _ => new NegateExpr(e),
    };

    public static Expr Sum(IEnumerable<Expr> terms)
    {
        if (terms is Expr[] array) return Sum(array.AsSpan());
        if (terms is ExprList list) return Sum(list.AsSpan());
        var flat = new List<Expr>();
        ConstantAccumulator constant = default;
        foreach (var t in terms) AddTerm(flat, ref constant, t, negate: false);
        return FinishSum(flat, constant);
    }

    public static Expr Sum(ExprList terms) => Sum(terms.AsSpan());

    public static Expr Sum(params ReadOnlySpan<Expr> terms)
    {
        var flat = new List<Expr>(terms.Length + 2);
        ConstantAccumulator constant = default;
        foreach (var t in terms) AddTerm(flat, ref constant, t, negate: false);
        return FinishSum(flat, constant);
    }

    private static Expr FinishSum(List<Expr> flat, ConstantAccumulator constant)
    {
        CancelOpposites(flat);
        if (!constant.IsZero) flat.Add(constant.ToExpr());
        return flat.Count switch
        {
            0 => ConstantExpr.Zero,
            1 => flat[0],
            _ => new SumExpr(flat),
        };
    }

    /// <summary>Removes pairs t, −t from a flattened sum (b − b is 0).</summary>
    private static void CancelOpposites(List<Expr> flat)
    {
        if (flat.Count < 2) return;
        for (var i = 0; i < flat.Count; i++)
        {
            var j = i + 1;
            while (j < flat.Count && !AreOpposite(flat[i], flat[j])) j++;
            if (j == flat.Count) continue;
            flat.RemoveAt(j);
            flat.RemoveAt(i);
            i--;
        }
    }

    /// <summary>Whether b is −a, tested without building −a.</summary>
    private static bool AreOpposite(Expr a, Expr b) =>
        a is NegateExpr n ? n.Operand.Equals(b) : b is NegateExpr m && m.Operand.Equals(a);

    public static Expr Difference(Expr a, Expr b) => Sum(a, Negate(b));

    private static void AddTerm(List<Expr> flat, ref ConstantAccumulator constant, Expr t, bool negate)
    {
        switch (t)
        {
            case SumExpr s:
                foreach (var c in s.Children) AddTerm(flat, ref constant, c, negate);
                break;
            case NegateExpr { Operand: SumExpr inner }:
                foreach (var c in inner.Children) AddTerm(flat, ref constant, c, !negate);
                break;
            case ConstantExpr c:
                constant.Add(c, negate);
                break;
            default:
                flat.Add(negate ? Negate(t) : t);
                break;
        }
    }

    public static Expr Product(IEnumerable<Expr> factors)
    {
        if (factors is Expr[] array) return Product(array.AsSpan());
        if (factors is ExprList list) return Product(list.AsSpan());
        var flat = new List<Expr>();
        var constant = ConstantAccumulator.One;
        var negative = false;
        foreach (var f in factors)
        {
            if (!AddFactor(flat, ref constant, ref negative, f)) return ConstantExpr.Zero;
        }
        return FinishProduct(flat, constant, negative);
    }

    public static Expr Product(ExprList factors) => Product(factors.AsSpan());

    public static Expr Product(params ReadOnlySpan<Expr> factors)
    {
        var flat = new List<Expr>(factors.Length + 1);
        var constant = ConstantAccumulator.One;
        var negative = false;
        foreach (var f in factors)
        {
            if (!AddFactor(flat, ref constant, ref negative, f)) return ConstantExpr.Zero;
        }
        return FinishProduct(flat, constant, negative);
    }

    private static Expr FinishProduct(List<Expr> flat, ConstantAccumulator constant, bool negative)
    {
        if (constant.IsNegative)
        {
            constant.Negate();
            negative = !negative;
        }
        if (!constant.IsOne) flat.Insert(0, constant.ToExpr());
        // x · (1/d) is x / d: one multiplication fewer (a shared reciprocal read only once ends up here)
        var reciprocal = flat.FindIndex(f => f is QuotientExpr { Numerator: ConstantExpr { Value: 1 } });
        if (reciprocal >= 0 && flat.Count >= 2)
        {
            var denominator = ((QuotientExpr)flat[reciprocal]).Denominator;
            flat.RemoveAt(reciprocal);
            var quotient = Quotient(Product(flat), denominator);
            return negative ? Negate(quotient) : quotient;
        }
        var result = flat.Count switch
        {
            0 => ConstantExpr.One,
            1 => flat[0],
            _ => new ProductExpr(flat),
        };
        return negative ? Negate(result) : result;
    }

    /// <returns>false when a factor is zero.</returns>
    private static bool AddFactor(List<Expr> flat, ref ConstantAccumulator constant, ref bool negative, Expr f)
    {
        switch (f)
        {
            case ProductExpr p:
                foreach (var c in p.Children)
                    if (!AddFactor(flat, ref constant, ref negative, c)) return false;
                return true;
            case NegateExpr n:
                negative = !negative;
                return AddFactor(flat, ref constant, ref negative, n.Operand);
            case ConstantExpr c:
                if (c.Value == 0) return false;
                constant.Multiply(c);
                return true;
            default:
                flat.Add(f);
                return true;
        }
    }

    public static Expr Quotient(Expr numerator, Expr denominator)
    {
        if (numerator is ConstantExpr { Value: 0 }) return ConstantExpr.Zero;
        if (denominator is ConstantExpr d)
        {
            if (d.Exact is { IsZero: false } r) return Product(ConstantExpr.From(r.Reciprocal()), numerator);
            if (d.Value != 0 && numerator is ConstantExpr n0) return new ConstantExpr(n0.Value / d.Value);
        }
        if (denominator is NegateExpr nd) return Negate(Quotient(numerator, nd.Operand));
        if (numerator is NegateExpr nn) return Negate(Quotient(nn.Operand, denominator));
        return new QuotientExpr(numerator, denominator);
    }

    public static Expr Power(Expr b, int exponent) => exponent switch
    {
        0 => ConstantExpr.One,
        1 => b,
        _ when b is ConstantExpr { Exact: { } r } && !(r.IsZero && exponent < 0) => ConstantExpr.From(r.Pow(exponent)),
        _ => new PowerExpr(b, exponent),
    };

    public static Expr Call(string function, params Expr[] arguments)
    {
        if (arguments.All(a => a is ConstantExpr) && MathFunctions.TryEvaluate(function, arguments.Select(a => ((ConstantExpr)a).Value).ToArray(), out var v))
            return new ConstantExpr(v);
        return new CallExpr(function, arguments);
    }

    /// <summary>Rebuilds one node through the normalizing constructors (its children already normal).</summary>
    public static Expr Normalize(Expr e) => e switch
    {
        SumExpr s => Sum(s.Children),
        ProductExpr p => Product(p.Children),
        NegateExpr n => Negate(n.Operand),
        QuotientExpr q => Quotient(q.Numerator, q.Denominator),
        PowerExpr p => Power(p.Base, p.Exponent),
        CallExpr c => Call(c.Function, c.Children.ToArray()),
        _ => e,
    };

    /// <summary>Folds constants exactly while both sides are exact, in doubles otherwise.</summary>
    private struct ConstantAccumulator
    {
        private Rational? _exact;
        private double _value;
        private bool _inexact;

        public static ConstantAccumulator One => new() { _exact = Rational.One, _value = 1 };

        public readonly bool IsZero => _inexact ? _value == 0 : (_exact ?? Rational.Zero).IsZero;
        public readonly bool IsOne => _inexact ? _value == 1 : (_exact ?? Rational.Zero).IsOne;
        public readonly bool IsNegative => _inexact ? _value < 0 : (_exact ?? Rational.Zero).Sign < 0;

        public void Add(ConstantExpr c, bool negate)
        {
            var sign = negate ? -1 : 1;
            if (!_inexact && c.Exact is { } r)
            {
                _exact = (_exact ?? Rational.Zero) + (negate ? -r : r);
                _value = _exact.Value.ToDouble();
            }
            else
            {
                _value = (_inexact ? _value : (_exact ?? Rational.Zero).ToDouble()) + sign * c.Value;
                _inexact = true;
            }
        }

        public void Multiply(ConstantExpr c)
        {
            if (!_inexact && c.Exact is { } r)
            {
                _exact = (_exact ?? Rational.One) * r;
                _value = _exact.Value.ToDouble();
            }
            else
            {
                _value = (_inexact ? _value : (_exact ?? Rational.One).ToDouble()) * c.Value;
                _inexact = true;
            }
        }

        public void Negate()
        {
            if (_inexact) _value = -_value;
            else
            {
                _exact = -(_exact ?? Rational.Zero);
                _value = _exact.Value.ToDouble();
            }
        }

        public readonly Expr ToExpr() => _inexact ? new ConstantExpr(_value) : ConstantExpr.From(_exact ?? Rational.Zero);
    }
}
