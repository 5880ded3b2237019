namespace GMac.Core.CodeGeneration;

/// <summary>Operation counts of a code block, the measure the optimizer minimizes.</summary>
public sealed record CodeStatistics(int Additions, int Multiplications, int Divisions, int Calls, int Negations, int Temporaries)
{
    /// <summary>A weighted cost: a division costs about four products, a function call about eight.</summary>
    public int Cost => Additions + Multiplications + 4 * Divisions + 8 * Calls;

    public int Operations => Additions + Multiplications + Divisions + Calls;

    public static CodeStatistics Of(CodeBlock block)
    {
        int adds = 0, muls = 0, divs = 0, calls = 0, negs = 0;
        foreach (var s in block.Statements)
        foreach (var e in s.Expressions)
            Count(e, insideSum: false, ref adds, ref muls, ref divs, ref calls, ref negs);
        return new CodeStatistics(adds, muls, divs, calls, negs, block.Temporaries.Count());
    }

    /// <summary>The <see cref="Cost"/> of one expression on its own.</summary>
    internal static int CostOf(Expr e)
    {
        int adds = 0, muls = 0, divs = 0, calls = 0, negs = 0;
        Count(e, insideSum: false, ref adds, ref muls, ref divs, ref calls, ref negs);
        return adds + muls + 4 * divs + 8 * calls;
    }

    private static void Count(Expr e, bool insideSum, ref int adds, ref int muls, ref int divs, ref int calls, ref int negs)
    {
        switch (e)
        {
            case SumExpr s:
                adds += s.Children.Count - 1;
                foreach (var c in s.Children) Count(c, insideSum: true, ref adds, ref muls, ref divs, ref calls, ref negs);
                return;
            case ProductExpr p:
                muls += p.Children.Count - 1;
                break;
            case QuotientExpr:
                divs++;
                break;
            case PowerExpr pw:
                muls += Math.Abs(pw.Exponent) - 1;
                if (pw.Exponent < 0) divs++;
                break;
            case CallExpr:
                calls++;
                break;
            case NegateExpr n:
                // a negated term of a sum is a subtraction, already counted
                if (!insideSum) negs++;
                Count(n.Operand, insideSum: false, ref adds, ref muls, ref divs, ref calls, ref negs);
                return;
        }
        foreach (var c in e.Children) Count(c, insideSum: false, ref adds, ref muls, ref divs, ref calls, ref negs);
    }

    public override string ToString() =>
        $"{Additions} additions/subtractions, {Multiplications} multiplications, {Divisions} divisions, {Calls} function calls, {Temporaries} temporaries";
}
