namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// What <see cref="SignedForm"/> would build for an expression, without building it: the sign left
/// to place, whether its magnitude negates for free, and the negations it needs. The search of
/// <see cref="SignPlacementPass"/> tries many flips and only needs these counts.
/// </summary>
internal readonly record struct SignCost(bool Negative, bool Flexible, bool IsConstant, int Cost)
{
    /// <summary>The negations of <see cref="SignedForm.Materialize"/>(<see cref="SignedForm.Of"/>(e), negative).</summary>
    public static int Of(Expr e, bool negative, Func<string, bool> isFlipped) => Placed(Analyze(e, isFlipped), negative);

    private static int Placed(SignCost s, bool negative) => s.Cost + (s.Negative != negative && !s.Flexible ? 1 : 0);

    private static SignCost Analyze(Expr e, Func<string, bool> isFlipped)
    {
        switch (e)
        {
            case ConstantExpr c:
                return new SignCost(c.Value < 0, true, true, 0);
            case VariableExpr v:
                return new SignCost(isFlipped(v.Name), false, false, 0);
            case NegateExpr n:
                var inner = Analyze(n.Operand, isFlipped);
                return inner with { Negative = !inner.Negative };
            case ProductExpr or QuotientExpr:
            {
                bool negative = false, flexible = false;
                var cost = 0;
                foreach (var f in e.Children)
                {
                    var a = Analyze(f, isFlipped);
                    negative ^= a.Negative;
                    flexible |= a.Flexible;
                    cost += a.Cost;
                }
                return new SignCost(negative, flexible, false, cost);
            }
            case SumExpr s:
                return AnalyzeSum(s, isFlipped);
            case PowerExpr { Exponent: var k } pw:
            {
                var b = Analyze(pw.Base, isFlipped);
                return new SignCost(false, false, false, k % 2 == 0 ? b.Cost : Placed(b, false));
            }
            case CallExpr call:
            {
                var cost = 0;
                foreach (var a in call.Children) cost += Placed(Analyze(a, isFlipped), false);
                return new SignCost(false, false, false, cost);
            }
            default:
                throw new InvalidOperationException($"Unknown expression node {e.GetType().Name}.");
        }
    }

    /// <summary>The four printable arrangements of <see cref="SignedForm"/>'s sums, in the same order.</summary>
    private static SignCost AnalyzeSum(SumExpr s, Func<string, bool> isFlipped)
    {
        var children = s.Children;
        var terms = children.Count <= 16 ? stackalloc SignCost[children.Count] : new SignCost[children.Count];
        var n = 0;
        var cost = 0;
        for (var pass = 0; pass < 2; pass++) // the printer's order: positive terms first
            foreach (var t in children)
                if (IsNegativeTerm(t) == (pass == 1))
                {
                    terms[n] = Analyze(t, isFlipped);
                    cost += terms[n++].Cost;
                }
        for (var arrangement = 0; arrangement < 4; arrangement++)
        {
            var (negative, swap) = (arrangement >= 2, arrangement % 2 == 1);
            if (!Printable(terms, negative, swap, out var mixed)) continue;
            // a mixed sum negates as n − (rest); an all-positive one through its first or second term
            var flexible = mixed || (!terms[0].IsConstant && terms[0].Flexible) || (!terms[1].IsConstant && terms[1].Flexible);
            return new SignCost(negative, flexible, false, cost);
        }
        return new SignCost(false, false, false, cost + SignedForm.Unprintable);
    }

    private static bool Printable(ReadOnlySpan<SignCost> terms, bool negative, bool swap, out bool mixed)
    {
        bool seenNegative = false, seenPositive = false;
        for (var i = 0; i < terms.Length; i++)
        {
            var t = swap && i < 2 ? terms[1 - i] : terms[i];
            var sign = t.Negative != negative;
            if (!sign && seenNegative) { mixed = false; return false; }
            seenNegative |= sign;
            seenPositive |= !sign;
        }
        mixed = seenNegative && seenPositive;
        return seenPositive;
    }

    private static bool IsNegativeTerm(Expr t) => t is NegateExpr || t is ConstantExpr { Value: < 0 };
}
