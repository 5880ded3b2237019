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
        var text = new StringBuilder();
        AppendScalar(text, scalar, null);
        return text.ToString();
    }

    /// <summary>
    /// The shared form <c>$0 = 1/(a + b); $1 = sqrt(x*$0 + 1); 2*$1 - x*$0</c>: every function or
    /// inverse atom is written once and named, so the text grows with the number of distinct
    /// subexpressions. The plain form repeats an atom's whole argument wherever the atom occurs,
    /// which for a common denominator of many terms runs to megabytes.
    /// <see cref="ScalarParser.ParseShared"/> reads it back.
    /// </summary>
    public static string FormatShared(Scalar scalar)
    {
        var names = new Dictionary<Atom, int>();
        var order = new List<Atom>();
        void Visit(Scalar s)
        {
            foreach (var term in s.TermArray)
            foreach (var factor in term.Monomial.FactorArray)
            {
                var atom = factor.Atom;
                if (atom.ArgumentArray.Length == 0 || names.ContainsKey(atom)) continue;
                foreach (var argument in atom.ArgumentArray) Visit(argument);
                names[atom] = order.Count; // arguments first, so each definition reads only earlier names
                order.Add(atom);
            }
        }
        Visit(scalar);
        var text = new StringBuilder();
        for (var i = 0; i < order.Count; i++)
        {
            text.Append('$').Append(i).Append(" = ");
            if (order[i].Kind == AtomKind.Inverse)
            {
                text.Append("1/(");
                AppendScalar(text, order[i].ArgumentArray[0], names);
                text.Append(')');
            }
            else AppendFunction(text, order[i], names);
            text.Append("; ");
        }
        AppendScalar(text, scalar, names);
        return text.ToString();
    }

    private static void AppendScalar(StringBuilder text, Scalar scalar, Dictionary<Atom, int>? names)
    {
        var terms = scalar.TermArray;
        if (terms.Length == 0)
        {
            text.Append('0');
            return;
        }
        for (var i = 0; i < terms.Length; i++) AppendTerm(text, terms[i], i == 0, names);
    }

    public static string FormatTerm(Term term, bool first)
    {
        var text = new StringBuilder();
        AppendTerm(text, term, first, null);
        return text.ToString();
    }

    public static string FormatAtom(Atom atom)
    {
        var text = new StringBuilder();
        AppendAtom(text, atom, null);
        return text.ToString();
    }

    private static void AppendTerm(StringBuilder text, Term term, bool first, Dictionary<Atom, int>? names)
    {
        // A named inverse atom is a plain factor $k^p; only an unnamed one is written as a denominator.
        bool InDenominator(Factor f) => f.Atom.Kind == AtomKind.Inverse && f.Power == 1 && names is null;
        var coefficient = term.Coefficient;
        if (coefficient.Sign < 0) text.Append(first ? "-" : " - ");
        else if (!first) text.Append(" + ");
        var magnitude = coefficient.Abs();

        var factors = term.Monomial.FactorArray;
        var numerator = 0;
        foreach (var factor in factors)
            if (factor.Power > 0 && !InDenominator(factor)) numerator++;

        var needsSeparator = false;
        if (!magnitude.IsOne || numerator == 0)
        {
            text.Append(magnitude.ToString());
            needsSeparator = true;
        }
        foreach (var factor in factors)
        {
            if (factor.Power < 0 || InDenominator(factor)) continue;
            if (needsSeparator) text.Append('*');
            needsSeparator = true;
            if (factor.Atom.Kind == AtomKind.Inverse && names is null)
            {
                // (s)^(-k) reads back as inv(s)^k, whereas /(s)^k would expand s^k first.
                AppendAtom(text, factor.Atom, names);
                text.Append("^(-").Append(factor.Power).Append(')');
            }
            else AppendPower(text, factor.Atom, factor.Power, names);
        }
        foreach (var factor in factors)
        {
            if (InDenominator(factor))
            {
                text.Append('/');
                AppendAtom(text, factor.Atom, names);
            }
            else if (factor.Power < 0)
            {
                text.Append('/');
                AppendPower(text, factor.Atom, -factor.Power, names);
            }
        }
    }

    private static void AppendPower(StringBuilder text, Atom atom, int power, Dictionary<Atom, int>? names)
    {
        AppendAtom(text, atom, names);
        if (power != 1) text.Append('^').Append(power);
    }

    private static void AppendAtom(StringBuilder text, Atom atom, Dictionary<Atom, int>? names)
    {
        if (names is not null && names.TryGetValue(atom, out var index))
        {
            text.Append('$').Append(index);
            return;
        }
        switch (atom.Kind)
        {
            case AtomKind.Variable:
            case AtomKind.Pi:
                text.Append(atom.Name);
                return;
            case AtomKind.Inverse:
                text.Append('(');
                AppendScalar(text, atom.ArgumentArray[0], names);
                text.Append(')');
                return;
            default:
                AppendFunction(text, atom, names);
                return;
        }
    }

    private static void AppendFunction(StringBuilder text, Atom atom, Dictionary<Atom, int>? names)
    {
        text.Append(atom.Name).Append('(');
        for (var i = 0; i < atom.ArgumentArray.Length; i++)
        {
            if (i > 0) text.Append(", ");
            AppendScalar(text, atom.ArgumentArray[i], names);
        }
        text.Append(')');
    }
}
