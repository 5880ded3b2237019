using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Rewrites polynomials of the inputs that do not change when a group of inputs is shifted
/// together (see <see cref="TranslationGroups"/>) so that they read only differences of those
/// inputs: one input of each group is pinned to zero and the others become their differences to
/// it, exactly as a careful hand derivation moves the origin onto a point first. The expanded form
/// a² − 2ab + b² loses all accuracy when a and b are large and close, (a − b)² loses none; the
/// difference form is also usually shorter, since the lowering then factors products of
/// differences instead of re-expanding them. A rewrite is kept unless it costs more than the
/// subtractions it introduces.
/// </summary>
public sealed class TranslationInvariancePass : IOptimizerPass
{
    /// <summary>Trees larger than this are not lifted: the symbolic work grows with their size.</summary>
    public const int MaxNodes = 600;

    /// <summary>Beyond this many inputs in one polynomial the group search is not tried.</summary>
    public const int MaxVariables = 24;

    /// <summary>Placeholder names of the differences while the pinned polynomial is lowered.</summary>
    private const string DifferencePrefix = "__gmac_difference_";

    public string Name => "translation-invariant differences";

    public CodeBlock Run(CodeBlock block)
    {
        var inputOrder = block.InputText.Keys.Select((k, i) => (k, i)).ToDictionary(p => p.k, p => p.i, StringComparer.Ordinal);
        // A sum left as it is has the sums inside it tried next, and equal sums recur across
        // statements: lifts (by node) and group searches (by polynomial) are made once per block.
        var lifts = new Dictionary<Expr, Scalar?>(ReferenceEqualityComparer.Instance);
        var groups = new Dictionary<Scalar, List<List<string>>>();
        return BlockRewriting.MapExpressions(block, e => BlockRewriting.ReplaceNodes(e, node =>
            node is SumExpr && node.Size <= MaxNodes ? Rewrite(node, inputOrder, lifts, groups) : null));
    }

    /// <summary>The difference form of one sum, or null to keep it (and look inside it).</summary>
    internal static Expr? Rewrite(Expr sum, IReadOnlyDictionary<string, int> inputOrder,
        Dictionary<Expr, Scalar?>? lifts = null, Dictionary<Scalar, List<List<string>>>? knownGroups = null)
    {
        if (!PolynomialLifting.TryLift(sum, lifts, out var polynomial) || !HasDegreeTwo(polynomial)) return null;
        var inputs = polynomial.Variables.Where(inputOrder.ContainsKey).OrderBy(v => inputOrder[v]).ToList();
        if (inputs.Count < 2 || inputs.Count > MaxVariables || polynomial.Variables.Any(v => v.StartsWith(DifferencePrefix, StringComparison.Ordinal))) return null;
        if (knownGroups is null || !knownGroups.TryGetValue(polynomial, out var groups))
        {
            groups = TranslationGroups.Find(polynomial, inputs);
            knownGroups?.Add(polynomial, groups);
        }
        if (groups.Count == 0) return null;

        var pinned = new Dictionary<string, Scalar>(StringComparer.Ordinal);
        var differences = new Dictionary<string, Expr>(StringComparer.Ordinal);
        foreach (var group in groups)
        {
            var anchor = group[0];
            pinned[anchor] = Scalar.Zero;
            foreach (var v in group.Skip(1))
            {
                var name = $"{DifferencePrefix}{differences.Count}";
                pinned[v] = Scalar.Variable(name);
                differences[name] = ExprFactory.Difference(ExprFactory.Variable(v), ExprFactory.Variable(anchor));
            }
        }
        var lowered = ScalarLowering.Lower(polynomial.Substitute(pinned));
        var rewritten = BlockRewriting.Substitute(lowered, differences);
        return Cost(rewritten) <= Cost(sum) + differences.Count ? rewritten : null;
    }

    /// <summary>Linear forms are already as good as they get; only products can cancel badly.</summary>
    private static bool HasDegreeTwo(Scalar polynomial) =>
        polynomial.Terms.Any(t => t.Monomial.Factors.Sum(f => f.Power) >= 2);

    private static int Cost(Expr e) =>
        new CodeBlock([new AssignmentStatement("value", e, true)], new Dictionary<string, string>(), new Dictionary<string, string>()).Statistics().Cost;
}
