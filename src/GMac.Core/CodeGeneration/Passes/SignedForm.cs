namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// An expression as a magnitude and a sign still to be placed, with the negations its magnitude
/// already needs (<see cref="Cost"/>). Every rewrite here is exact in floating point: a sign moves
/// between factors, a − b becomes −(b − a), and a sum keeps the order in which the printer
/// evaluates its terms (positive terms first), so the computed value is the same to the last bit,
/// but for the sign of an exact zero (b − a is +0 where −(a − b) is −0).
/// </summary>
internal sealed record SignedForm(Expr Magnitude, bool Negative, int Cost)
{
    /// <summary>Added to the cost of a sum whose new signs cannot be printed in its evaluation order.</summary>
    public const int Unprintable = 1_000_000;

    /// <param name="isFlipped">Whether a variable is a temporary that now holds the negated value.</param>
    public static SignedForm Of(Expr e, Func<string, bool> isFlipped)
    {
        switch (e)
        {
            case ConstantExpr c:
                return new SignedForm(c.Value < 0 ? ExprFactory.Negate(c) : c, c.Value < 0, 0);
            case VariableExpr v:
                return new SignedForm(v, isFlipped(v.Name), 0);
            case NegateExpr n:
                var inner = Of(n.Operand, isFlipped);
                return inner with { Negative = !inner.Negative };
            case ProductExpr p:
            {
                var factors = p.Children.Select(f => Of(f, isFlipped)).ToArray();
                return new SignedForm(new ProductExpr(factors.Select(f => f.Magnitude).ToArray()),
                    factors.Count(f => f.Negative) % 2 == 1, factors.Sum(f => f.Cost));
            }
            case QuotientExpr q:
            {
                var (n, d) = (Of(q.Numerator, isFlipped), Of(q.Denominator, isFlipped));
                return new SignedForm(new QuotientExpr(n.Magnitude, d.Magnitude), n.Negative != d.Negative, n.Cost + d.Cost);
            }
            case SumExpr s:
                return OfSum(s, isFlipped);
            case PowerExpr { Exponent: var k } pw when k % 2 == 0:
            {
                var b = Of(pw.Base, isFlipped); // an even power does not see the base's sign
                return new SignedForm(new PowerExpr(b.Magnitude, k), false, b.Cost);
            }
            case PowerExpr pw:
            {
                var (b, cost) = Materialize(Of(pw.Base, isFlipped), negative: false);
                return new SignedForm(new PowerExpr(b, pw.Exponent), false, cost);
            }
            case CallExpr call:
            {
                var args = call.Children.Select(a => Materialize(Of(a, isFlipped), negative: false)).ToArray();
                return new SignedForm(new CallExpr(call.Function, args.Select(a => a.Value).ToArray()), false, args.Sum(a => a.Cost));
            }
            default:
                throw new InvalidOperationException($"Unknown expression node {e.GetType().Name}.");
        }
    }

    /// <summary>The expression for the value (or its negation), with the negations it costs.</summary>
    public static (Expr Value, int Cost) Materialize(SignedForm s, bool negative)
    {
        if (s.Negative == negative) return (s.Magnitude, s.Cost);
        if (IsFlexible(s.Magnitude)) return (Flip(s.Magnitude), s.Cost);
        // "−a − b" rather than "−(a + b)": the same one negation, in the printer's usual shape
        if (s.Magnitude is SumExpr sum) return (new SumExpr(sum.Children.Select(NegatedTerm).ToArray()), s.Cost + 1);
        return (new NegateExpr(s.Magnitude), s.Cost + 1);
    }

    /// <summary>The negations the printed text of an expression costs as it stands.</summary>
    public static int PrintedNegations(Expr e) => e switch
    {
        NegateExpr n => 1 + PrintedNegations(n.Operand),
        SumExpr s => (s.Children.All(IsNegativeTerm) ? 1 : 0)
                     + s.Children.Sum(t => t is NegateExpr n ? PrintedNegations(n.Operand) : PrintedNegations(t)),
        _ => e.Children.Sum(PrintedNegations),
    };

    /// <summary>Whether a magnitude can be negated exactly without a negation instruction.</summary>
    private static bool IsFlexible(Expr m) => m switch
    {
        ConstantExpr => true,
        ProductExpr p => p.Children.Any(IsFlexible),
        QuotientExpr q => IsFlexible(q.Numerator) || IsFlexible(q.Denominator),
        SumExpr s when s.Children.Any(IsNegativeTerm) => true,
        SumExpr s => s.Children.Take(2).Any(t => t is not ConstantExpr && IsFlexible(t)),
        _ => false,
    };

    /// <summary>The exact negation of a flexible magnitude, with no negation left to compute.</summary>
    private static Expr Flip(Expr m)
    {
        switch (m)
        {
            case ConstantExpr c:
                return ExprFactory.Negate(c);
            case ProductExpr p:
            {
                var factors = p.Children.ToArray();
                var i = Array.FindIndex(factors, IsFlexible);
                factors[i] = Flip(factors[i]);
                return new ProductExpr(factors);
            }
            case QuotientExpr q:
                return IsFlexible(q.Numerator) ? new QuotientExpr(Flip(q.Numerator), q.Denominator) : new QuotientExpr(q.Numerator, Flip(q.Denominator));
            case SumExpr s when s.Children.Any(IsNegativeTerm):
            {
                // p1 + … − n evaluated left to right, negated: n − (p1 + …), the same rounding
                var terms = s.Children;
                var rest = terms.Count == 2 ? NegatedTerm(terms[0]) : new NegateExpr(new SumExpr(terms.Take(terms.Count - 1).ToArray()));
                return new SumExpr([NegatedTerm(terms[^1]), rest]);
            }
            case SumExpr s:
            {
                // all positive: the first two terms commute, so either may lead with its sign flipped
                var terms = s.Children.ToList();
                var k = terms[0] is not ConstantExpr && IsFlexible(terms[0]) ? 0 : 1;
                var lead = Flip(terms[k]);
                terms.RemoveAt(k);
                return new SumExpr(terms.Select(NegatedTerm).Prepend(lead).ToArray());
            }
            default:
                throw new InvalidOperationException($"{m} cannot be negated for free.");
        }
    }

    /// <summary>
    /// A sum keeps the order in which its text evaluates it (positive terms first). With its terms'
    /// new signs it is printable as it is, with its first two terms swapped, or negated as a whole;
    /// when none of these keeps that order it is marked <see cref="Unprintable"/>.
    /// </summary>
    private static SignedForm OfSum(SumExpr s, Func<string, bool> isFlipped)
    {
        var ordered = s.Children.OrderBy(t => IsNegativeTerm(t) ? 1 : 0).Select(t => Of(t, isFlipped)).ToArray();
        var cost = ordered.Sum(t => t.Cost);
        foreach (var negative in new[] { false, true })
        foreach (var swap in new[] { false, true })
        {
            var terms = ordered.ToArray();
            if (swap) (terms[0], terms[1]) = (terms[1], terms[0]);
            var signs = terms.Select(t => t.Negative != negative).ToArray();
            if (signs.All(n => n) || !PositivesFirst(signs)) continue; // "−a − b" would need a negation
            var printed = terms.Select((t, i) => signs[i] ? NegatedTerm(t.Magnitude) : t.Magnitude).ToArray();
            return new SignedForm(new SumExpr(printed), negative, cost);
        }
        return new SignedForm(s, false, cost + Unprintable);
    }

    private static bool PositivesFirst(bool[] negativeSigns)
    {
        for (var i = 1; i < negativeSigns.Length; i++)
            if (negativeSigns[i - 1] && !negativeSigns[i]) return false;
        return true;
    }

    private static bool IsNegativeTerm(Expr t) => t is NegateExpr || t is ConstantExpr { Value: < 0 };

    private static Expr NegatedTerm(Expr t) => t is ConstantExpr c ? ExprFactory.Negate(c) : t is NegateExpr n ? n.Operand : new NegateExpr(t);
}
