using System.Text;

namespace GMac.Core.Symbolic;

/// <summary>
/// Prints scalars as conventional infix text (<c>2*x*y - sin(a)^2</c>, <c>1/2*x</c>, <c>x/(a + b)</c>)
/// that <see cref="ScalarParser"/> reads back to the very same object.
/// </summary>
internal static class ScalarPrinter
{
    public static string Format(Scalar scalar)
    {
        var terms = scalar.TermArray;
        if (terms.Length == 0) return "0";
        var text = new StringBuilder();
        for (var i = 0; i < terms.Length; i++) AppendTerm(text, terms[i], i == 0);
        return text.ToString();
    }

    public static string FormatTerm(Term term, bool first)
    {
        var text = new StringBuilder();
        AppendTerm(text, term, first);
        return text.ToString();
    }

    public static string FormatAtom(Atom atom)
    {
        var text = new StringBuilder();
        AppendAtom(text, atom);
        return text.ToString();
    }

    private static void AppendTerm(StringBuilder text, Term term, bool first)
    {
        var coefficient = term.Coefficient;
        if (coefficient.Sign < 0) text.Append(first ? "-" : " - ");
        else if (!first) text.Append(" + ");
        var magnitude = coefficient.Abs();

        var factors = term.Monomial.FactorArray;
        var numerator = 0;
        foreach (var factor in factors)
            if (factor.Power > 0 && !(factor.Atom.Kind == AtomKind.Inverse && factor.Power == 1)) numerator++;

        var needsSeparator = false;
        if (!magnitude.IsOne || numerator == 0)
        {
            text.Append(magnitude.ToString());
            needsSeparator = true;
        }
        foreach (var factor in factors)
        {
            if (factor.Power < 0 || (factor.Atom.Kind == AtomKind.Inverse && factor.Power == 1)) continue;
            if (needsSeparator) text.Append('*');
            needsSeparator = true;
            if (factor.Atom.Kind == AtomKind.Inverse)
            {
                // (s)^(-k) reads back as inv(s)^k, whereas /(s)^k would expand s^k first.
                AppendAtom(text, factor.Atom);
                text.Append("^(-").Append(factor.Power).Append(')');
            }
            else AppendPower(text, factor.Atom, factor.Power);
        }
        foreach (var factor in factors)
        {
            if (factor.Atom.Kind == AtomKind.Inverse)
            {
                if (factor.Power != 1) continue;
                text.Append('/');
                AppendAtom(text, factor.Atom);
            }
            else if (factor.Power < 0)
            {
                text.Append('/');
                AppendPower(text, factor.Atom, -factor.Power);
            }
        }
    }

    private static void AppendPower(StringBuilder text, Atom atom, int power)
    {
        AppendAtom(text, atom);
        if (power != 1) text.Append('^').Append(power);
    }

    private static void AppendAtom(StringBuilder text, Atom atom)
    {
        switch (atom.Kind)
        {
            case AtomKind.Variable:
            case AtomKind.Pi:
                text.Append(atom.Name);
                return;
            case AtomKind.Inverse:
                text.Append('(').Append(Format(atom.ArgumentArray[0])).Append(')');
                return;
            default:
                text.Append(atom.Name).Append('(');
                for (var i = 0; i < atom.ArgumentArray.Length; i++)
                {
                    if (i > 0) text.Append(", ");
                    text.Append(Format(atom.ArgumentArray[i]));
                }
                text.Append(')');
                return;
        }
    }
}
