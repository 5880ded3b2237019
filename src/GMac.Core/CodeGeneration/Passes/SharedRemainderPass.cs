using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Fractions over one denominator D whose numerators divide by D up to a common remainder: with
/// Nᵢ = qᵢ·D + cᵢ·mᵢ·g (mᵢ a monomial, cᵢ a constant), each Nᵢ/D becomes qᵢ + cᵢ·mᵢ·k, where
/// k = g/D is computed once. A rejection v − (v·a/|a|²) a reaches the block as components
/// (vₓ(a_y² + a_z²) − aₓ(a_y v_y + a_z v_z))/|a|², whose vₓaₓ² terms cancelled so that every
/// component is computed apart; division by |a|² gives vₓ − aₓ·(a·v)/|a|², sharing the dot
/// product and the quotient as a hand derivation does. Every lead atom of D is tried for each
/// numerator; the remainder shared by the most saving set of two or more fractions is taken, and only when
/// the block then costs less (repeated subexpressions counted once).
/// </summary>
public sealed class SharedRemainderPass : IOptimizerPass
{
    private const int MaxNumeratorTerms = 48;
    private const int MaxDenominatorTerms = 8;
    private const int MaxRewrites = 4;

    public string Name => "shared remainders of fractions";

    public CodeBlock Run(CodeBlock block)
    {
        if (block.Statements.Any(s => s is VerbatimStatement)) return block;
        for (var round = 0; round < MaxRewrites; round++)
        {
            var better = BestRewrite(block);
            if (better is null) break;
            block = better;
        }
        return block;
    }

    /// <summary>A fraction statement: its position, sign, numerator value and the denominator as written.</summary>
    private sealed record Fraction(int Index, bool Negated, Scalar Numerator, Scalar Denominator, Expr Reciprocal);

    /// <summary>One way to write a fraction: q + c·m·(g/D).</summary>
    private sealed record Option(Fraction Of, Scalar Quotient, Rational Coefficient, Monomial Multiplier);

    private static CodeBlock? BestRewrite(CodeBlock block)
    {
        var values = new PolynomialValues(block);
        var options = new Dictionary<(Scalar D, Scalar G), List<Option>>();
        // one fraction alone cannot share its remainder
        foreach (var fraction in Fractions(block, values).GroupBy(f => f.Denominator).Where(g => g.Count() > 1).SelectMany(g => g))
        foreach (var first in Rewrites.PolynomialRemainder.Candidates(fraction.Denominator))
        {
            if (!Rewrites.PolynomialRemainder.TryDivide(fraction.Numerator, fraction.Denominator, first, out var q, out var r)) continue;
            if (Scalar.IsZero(q) || r.Terms.Count < 2) continue;
            var (c, m, g) = Content(r);
            if (!options.TryGetValue((fraction.Denominator, g), out var list)) options[(fraction.Denominator, g)] = list = [];
            if (list.All(o => o.Of.Index != fraction.Index)) list.Add(new Option(fraction, q, c, m));
        }
        if (!options.Values.Any(list => list.Count > 1)) return null;

        var baseline = Rewrites.SharedCost.Of(new DeadCodePass().Run(block));
        CodeBlock? best = null;
        var bestCost = baseline;
        foreach (var ((_, g), list) in options)
        {
            if (list.Count < 2) continue;
            var candidate = new DeadCodePass().Run(Apply(block, g, list));
            var cost = Rewrites.SharedCost.Of(candidate);
            if (cost < bestCost) (best, bestCost) = (candidate, cost);
        }
        return best;
    }

    /// <summary>
    /// Assignments N·r with r = 1/D a temporary, or N/D, whose N and D are polynomials, and that
    /// share their written denominator with another: only those are lifted, which spares most
    /// blocks any polynomial work.
    /// </summary>
    private static IEnumerable<Fraction> Fractions(CodeBlock block, PolynomialValues values)
    {
        var reciprocals = new Dictionary<string, Expr>(StringComparer.Ordinal);
        var shapes = new List<(int Index, bool Negated, Expr Numerator, Expr Denominator, Expr Reciprocal)>();
        for (var i = 0; i < block.Statements.Count; i++)
        {
            if (block.Statements[i] is not AssignmentStatement a) continue;
            if (!a.IsOutput && a.Value is QuotientExpr { Numerator: ConstantExpr { Value: 1 } } rcp) reciprocals[a.Target] = rcp.Denominator;
            var negated = a.Value is NegateExpr;
            var e = a.Value is NegateExpr n ? n.Operand : a.Value;
            if (e is QuotientExpr q && q.Numerator is not ConstantExpr)
                shapes.Add((i, negated, q.Numerator, q.Denominator, q.Denominator));
            else if (e is ProductExpr p && p.Children.OfType<VariableExpr>().FirstOrDefault(v => reciprocals.ContainsKey(v.Name)) is { } r)
                shapes.Add((i, negated, ExprFactory.Product(p.Children.Where(c => !ReferenceEquals(c, r))), reciprocals[r.Name], r));
        }
        foreach (var group in shapes.GroupBy(f => f.Reciprocal).Where(g => g.Count() > 1))
        foreach (var (index, negated, numerator, denominator, reciprocal) in group)
        {
            if (values.Of(numerator) is not { } num || values.Of(denominator) is not { } den) continue;
            if (num.Terms.Count < 2 || num.Terms.Count > MaxNumeratorTerms || den.Terms.Count < 2 || den.Terms.Count > MaxDenominatorTerms) continue;
            yield return new Fraction(index, negated, num, den, reciprocal);
        }
    }

    /// <summary>r = c·m·g with m the monomial every term shares and g's first coefficient 1.</summary>
    private static (Rational C, Monomial M, Scalar G) Content(Scalar r)
    {
        var powers = r.Terms[0].Monomial.Factors.Where(f => f.Power > 0).ToDictionary(f => f.Atom, f => f.Power);
        foreach (var t in r.Terms.Skip(1))
        {
            var here = t.Monomial.Factors.ToDictionary(f => f.Atom, f => f.Power);
            foreach (var atom in powers.Keys.ToArray())
            {
                var p = Math.Min(powers[atom], here.GetValueOrDefault(atom));
                if (p > 0) powers[atom] = p; else powers.Remove(atom);
            }
        }
        var m = Monomial.Create(powers.Select(kv => new Factor(kv.Key, kv.Value)));
        var g = Scalar.FromTerms(r.Terms.Select(t => new Term(t.Coefficient, Monomial.Create(t.Monomial.Factors
            .Select(f => new Factor(f.Atom, f.Power - powers.GetValueOrDefault(f.Atom))).Where(f => f.Power != 0)))));
        var c = g.Terms[0].Coefficient;
        return (c, m, Scalar.Scale(g, Rational.One / c));
    }

    /// <summary>The block with g and k = g/D named before the first fraction, and each fraction rewritten.</summary>
    private static CodeBlock Apply(CodeBlock block, Scalar g, List<Option> options)
    {
        var used = new HashSet<string>(block.InputText.Keys, StringComparer.Ordinal);
        foreach (var a in block.Statements.OfType<AssignmentStatement>()) used.Add(a.Target);
        var gName = Fresh(used, "rem");
        var kName = Fresh(used, "rem");
        var first = options.Min(o => o.Of.Index);
        var firstFraction = options.First(o => o.Of.Index == first).Of;
        var k = ExprFactory.Quotient(ExprFactory.Variable(gName), firstFraction.Reciprocal);
        if (firstFraction.Reciprocal is VariableExpr r) k = ExprFactory.Product(ExprFactory.Variable(gName), r);
        var statements = new List<CodeStatement>();
        for (var i = 0; i < block.Statements.Count; i++)
        {
            if (i == first)
            {
                statements.Add(new AssignmentStatement(gName, ScalarLowering.Lower(g), false));
                statements.Add(new AssignmentStatement(kName, k, false));
            }
            var option = options.FirstOrDefault(o => o.Of.Index == i);
            var s = (AssignmentStatement)block.Statements[i];
            if (option is null)
            {
                statements.Add(s);
                continue;
            }
            var value = option.Quotient + Scalar.FromTerm(option.Coefficient, option.Multiplier) * Scalar.Variable(kName);
            statements.Add(s with { Value = ScalarLowering.Lower(option.Of.Negated ? -value : value) });
        }
        return block.WithStatements(statements);
    }

    private static string Fresh(HashSet<string> used, string prefix)
    {
        for (var i = 0; ; i++)
            if (used.Add($"{prefix}{i}")) return $"{prefix}{i}";
    }
}
