using GMac.Core.CodeGeneration.Passes;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// A form of a block whose outputs move with its positions (<see cref="InputPoint.IsPosition"/>):
/// the block run with one position (the anchor) at the origin and the others as their differences
/// to it, and its outputs then moved back by the anchor. The sphere through p1 … p4 is the sphere
/// through 0, p2 − p1, p3 − p1, p4 − p1 (whose ni coefficient is zero) moved by p1: the squares
/// ½|pᵢ|² of absolute coordinates, which lose digits far from the origin, are never formed, and the
/// determinants lose the terms of the point at the origin.
/// <para>
/// How the outputs move is not assumed but found: with every moved position written a + dᵢ, each
/// output, expanded, must be a combination of the outputs at a = 0 with coefficients that are
/// polynomials of a (<see cref="Law"/>). Where it is not (an output that is not a polynomial, or
/// one that does not move with the points) there is no such form.
/// </para>
/// </summary>
internal static class OriginShift
{
    /// <summary>Outputs with more terms than this, expanded, are not examined: the expansion in a + dᵢ grows with the degree.</summary>
    public const int MaxTerms = 400;

    private const string DifferencePrefix = "__gmac_shift_d";
    private const string ShiftedPrefix = "__gmac_shift_o";
    private const string MovedPrefix = "__gmac_shift_t";

    /// <summary>
    /// How the outputs move: <see cref="Laws"/>[k] is output k as a polynomial of the anchor's
    /// coordinates and the variables <c>ShiftedPrefix + j</c> (output j of the shifted block).
    /// </summary>
    public sealed record Law(InputPoint Anchor, IReadOnlyList<InputPoint> Moved, IReadOnlyList<string> Outputs, IReadOnlyList<Scalar> Laws);

    /// <summary>The law by which the block's outputs move with its first layout of positions, or null when they do not.</summary>
    public static Law? Find(CodeBlock block)
    {
        try
        {
            return FindExpanding(block);
        }
        catch (Algebra.AlgebraException e) when (e.ExceedsLimit)
        {
            return null; // outputs too large to expand in p1 + dᵢ: the forms already built stand
        }
    }

    private static Law? FindExpanding(CodeBlock block)
    {
        if (block.Statements.Any(s => s is not AssignmentStatement)) return null;
        var positions = block.Points.Where(p => p.IsPosition).GroupBy(p => p.Layout).FirstOrDefault(g => g.Count() >= 2)?.ToList();
        if (positions is null) return null;
        var outputs = block.Outputs.ToList();
        if (outputs.Count == 0 || outputs.Select(o => o.Target).Distinct(StringComparer.Ordinal).Count() != outputs.Count) return null;

        var lifted = LiftOutputs(block, outputs);
        if (lifted is null) return null;

        var anchor = positions[0];
        var moved = positions.Skip(1).ToList();
        var anchorNames = new HashSet<string>(anchor.Coordinates, StringComparer.Ordinal);
        var toDifferences = new Dictionary<string, Scalar>(StringComparer.Ordinal);
        var differenceCount = 0;
        foreach (var p in moved)
            for (var c = 0; c < p.Coordinates.Count; c++)
                toDifferences[p.Coordinates[c]] = Scalar.Variable(anchor.Coordinates[c]) + Scalar.Variable($"{DifferencePrefix}{differenceCount++}");
        var atOrigin = anchor.Coordinates.ToDictionary(c => c, _ => Scalar.Zero, StringComparer.Ordinal);

        var expanded = lifted.Select(o => o.Substitute(toDifferences)).ToList();
        var shifted = expanded.Select(o => o.Substitute(atOrigin)).ToList();
        var span = new PolynomialSpan(shifted);
        var laws = new List<Scalar>();
        foreach (var output in expanded)
        {
            var law = Scalar.Zero;
            foreach (var (anchorPart, coefficient) in ByAnchorMonomial(output, anchorNames))
            {
                if (span.Express(coefficient) is not { } combination) return null;
                foreach (var (j, w) in combination)
                    law += Scalar.FromTerm(w, anchorPart) * Scalar.Variable($"{ShiftedPrefix}{j}");
            }
            laws.Add(law);
        }
        // outputs that stay where they are (a distance, a radius) are the translation-invariance pass's work
        if (laws.Select((l, k) => l == Scalar.Variable($"{ShiftedPrefix}{k}")).All(same => same)) return null;
        return new Law(anchor, moved, outputs.Select(o => o.Target).ToList(), laws);
    }

    /// <summary>
    /// The block computing its outputs at the origin and moving them back by <see cref="Law.Anchor"/>.
    /// An output whose law is quadratic in the anchor reuses the moved outputs where that is
    /// shorter: the ni coefficient of a moved dual sphere, p·E′ + ½ No′|p|² with E = E′ + No′ p,
    /// is ½ p·(E′ + E).
    /// </summary>
    public static CodeBlock Apply(CodeBlock block, Law law)
    {
        var statements = new List<CodeStatement>();
        var replacements = law.Anchor.Coordinates.ToDictionary(c => c, _ => ExprFactory.Constant(0), StringComparer.Ordinal);
        var differenceCount = 0;
        foreach (var p in law.Moved)
            for (var c = 0; c < p.Coordinates.Count; c++)
            {
                var name = $"{DifferencePrefix}{differenceCount++}";
                statements.Add(new AssignmentStatement(name, ExprFactory.Difference(ExprFactory.Variable(p.Coordinates[c]), ExprFactory.Variable(law.Anchor.Coordinates[c])), false));
                replacements[p.Coordinates[c]] = ExprFactory.Variable(name);
            }
        var outputIndex = law.Outputs.Select((o, k) => (o, k)).ToDictionary(p => p.o, p => p.k, StringComparer.Ordinal);
        foreach (var s in block.Statements)
        {
            var a = (AssignmentStatement)BlockRewriting.Substitute(s, replacements);
            statements.Add(a.IsOutput ? new AssignmentStatement($"{ShiftedPrefix}{outputIndex[a.Target]}", a.Value, false) : a);
        }

        var anchor = law.Anchor.Coordinates;
        var forms = law.Laws.Select(l => ScalarLowering.Lower(l)).ToArray();
        var reused = new HashSet<int>();
        for (var k = 0; k < law.Laws.Count; k++)
        {
            if (ReusingMoved(law.Laws, k, anchor) is not var (form, reads) || CodeStatistics.CostOf(form) >= CodeStatistics.CostOf(forms[k])) continue;
            forms[k] = form;
            reused.UnionWith(reads);
        }
        foreach (var r in reused) statements.Add(new AssignmentStatement($"{MovedPrefix}{r}", ScalarLowering.Lower(law.Laws[r]), false));
        for (var k = 0; k < law.Outputs.Count; k++)
            statements.Add(new AssignmentStatement(law.Outputs[k], reused.Contains(k) ? ExprFactory.Variable($"{MovedPrefix}{k}") : forms[k], true));
        return block.WithStatements(statements);
    }

    /// <summary>
    /// Law k, of degree n ≥ 2 in the anchor a, written as Σ μ aᵢ·(moved output r) + a rest of degree
    /// below n, over the outputs r whose laws have degree n − 1: the μ make the degree-n parts cancel.
    /// </summary>
    private static (Expr Form, List<int> Reads)? ReusingMoved(IReadOnlyList<Scalar> laws, int k, IReadOnlyList<string> anchor)
    {
        var anchorNames = new HashSet<string>(anchor, StringComparer.Ordinal);
        var degree = laws.Select(l => AnchorDegree(l, anchorNames)).ToArray();
        if (degree[k] < 2) return null;
        var pairs = new List<(int R, string A)>();
        for (var r = 0; r < laws.Count; r++)
            if (degree[r] == degree[k] - 1)
                pairs.AddRange(anchor.Select(a => (r, a)));
        if (pairs.Count == 0) return null;
        var top = pairs.Select(p => Scalar.Variable(p.A) * Top(laws[p.R], anchorNames, degree[p.R])).ToList();
        if (new PolynomialSpan(top).Express(Top(laws[k], anchorNames, degree[k])) is not { } mu) return null;
        var rest = laws[k];
        var reuse = Scalar.Zero;
        foreach (var (j, w) in mu)
        {
            var (r, a) = pairs[j];
            rest -= Scalar.Scale(Scalar.Variable(a) * laws[r], w);
            reuse += Scalar.Scale(Scalar.Variable(a) * Scalar.Variable($"{MovedPrefix}{r}"), w);
        }
        return (ScalarLowering.Lower(reuse + rest), mu.Keys.Select(j => pairs[j].R).Distinct().ToList());
    }

    /// <summary>The polynomials the outputs hold, looked through the temporaries; null where one is not a polynomial of the inputs or is too long.</summary>
    private static List<Scalar>? LiftOutputs(CodeBlock block, List<AssignmentStatement> outputs)
    {
        var temporaries = new TemporaryPolynomials(block, MaxTerms);
        var result = new List<Scalar>();
        foreach (var o in outputs)
        {
            // a temporary without a polynomial (a quotient, a call), or any other name that is not
            // an input, stays a variable: then the output is not a polynomial of the inputs
            var p = PolynomialLifting.LiftThrough(o.Value, temporaries.Of);
            if (p is null || p.Terms.Count > MaxTerms || !p.Variables.All(block.InputText.ContainsKey)) return null;
            result.Add(p);
        }
        return result;
    }

    /// <summary>The terms of <paramref name="polynomial"/> grouped by their part in the anchor's coordinates.</summary>
    private static IEnumerable<(Monomial AnchorPart, Scalar Coefficient)> ByAnchorMonomial(Scalar polynomial, HashSet<string> anchorNames) =>
        polynomial.Terms
            .Select(t => (Anchor: Monomial.Create(t.Monomial.Factors.Where(f => IsAnchor(f, anchorNames))),
                Term: new Term(t.Coefficient, Monomial.Create(t.Monomial.Factors.Where(f => !IsAnchor(f, anchorNames))))))
            .GroupBy(t => t.Anchor)
            .Select(g => (g.Key, Scalar.FromTerms(g.Select(t => t.Term))));

    private static bool IsAnchor(Factor f, HashSet<string> anchorNames) => f.Atom.Kind == AtomKind.Variable && anchorNames.Contains(f.Atom.Name);

    private static int AnchorDegree(Monomial m, HashSet<string> anchorNames) => m.Factors.Where(f => IsAnchor(f, anchorNames)).Sum(f => f.Power);

    private static int AnchorDegree(Scalar s, HashSet<string> anchorNames) => s.Terms.Count == 0 ? 0 : s.Terms.Max(t => AnchorDegree(t.Monomial, anchorNames));

    private static Scalar Top(Scalar s, HashSet<string> anchorNames, int degree) =>
        Scalar.FromTerms(s.Terms.Where(t => AnchorDegree(t.Monomial, anchorNames) == degree));
}
