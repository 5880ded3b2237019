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
/// A polynomial that moves with the points instead (the moment p × q of the line through p and
/// q, ½(|q|² − |p|²) in a circle through points) is written over the differences of the points
/// (<see cref="CodeBlock.Points"/>) to one of them where what is left of the anchor alone is at
/// most linear: p × q = p × (q − p). Only when <paramref name="differencesEverywhere"/>, where the
/// polynomial over the differences costs no more than the expanded one (the subtractions, often
/// shared, are not counted): the generator builds such a form as a further candidate where the
/// others lose accuracy, and keeps it where the whole block's ranking says so.
/// </summary>
public sealed class TranslationInvariancePass(bool differencesEverywhere = false) : IOptimizerPass
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
        var points = differencesEverywhere ? block.Points : [];
        var held = points.Count < 2 ? null : new HeldPolynomials(block);
        return BlockRewriting.MapExpressions(block, e => BlockRewriting.ReplaceNodes(e, node =>
            node is SumExpr && node.Size <= MaxNodes
                ? Rewrite(node, inputOrder, lifts, groups) ?? Covariant(node, points, lifts, held)
                : null));
    }

    /// <summary>Beyond this many terms a temporary's polynomial is not looked through.</summary>
    private const int MaxHeldTerms = 64;

    /// <summary>
    /// The polynomials of the inputs that the block's temporaries hold, where they hold one, with
    /// the temporaries that hold anything else (a quotient, a call) left as variables of their own.
    /// </summary>
    private sealed class HeldPolynomials(CodeBlock block)
    {
        private readonly TemporaryPolynomials _held = new(block, MaxHeldTerms, MaxNodes);

        private readonly Dictionary<string, int> _uses = BlockRewriting.UseCounts(block.Statements);

        private readonly Dictionary<string, bool> _waits = new(StringComparer.Ordinal);

        public bool IsTemporary(string name) => _held.IsTemporary(name);

        /// <summary>Whether the value of <paramref name="e"/> waits, through the temporaries it reads, for one that holds no polynomial (a quotient, a call).</summary>
        public bool WaitsOnOther(Expr e) => e.DescendantsAndSelf().OfType<VariableExpr>().Any(v => WaitsOnOther(v.Name));

        private bool WaitsOnOther(string name)
        {
            if (!_held.Definitions.TryGetValue(name, out var value)) return false;
            if (_waits.TryGetValue(name, out var known)) return known;
            _waits[name] = false;
            return _waits[name] = Of(name) is null || WaitsOnOther(value);
        }

        /// <summary>
        /// The sum with the temporaries that only it reads written in place, one level: what the
        /// sum really costs where a product of it was split off (bp_in2 * t1 − pair with pair = bp_in1 * t2).
        /// </summary>
        public Expr WithOwnTemporaries(Expr sum) => BlockRewriting.Substitute(sum, sum.DescendantsAndSelf().OfType<VariableExpr>()
            .Where(v => _uses.GetValueOrDefault(v.Name) == 1 && _held.Definitions.ContainsKey(v.Name)).DistinctBy(v => v.Name)
            .ToDictionary(v => v.Name, v => _held.Definitions[v.Name], StringComparer.Ordinal));

        public Scalar? Of(string name) => _held.Of(name);
    }

    /// <summary>
    /// The sum written over differences of the points it reads to one anchor point, or null. Each
    /// layout of points is tried with every point it reads as the anchor; the cheapest form whose
    /// anchor-only part (the value with every point at the anchor) is at most linear is kept.
    /// </summary>
    internal static Expr? Covariant(Expr sum, IReadOnlyList<InputPoint> points, Dictionary<Expr, Scalar?>? lifts = null) =>
        Covariant(sum, points, lifts, null);

    /// <param name="held">
    /// The polynomials the block's temporaries hold: a sum over temporaries that is a polynomial of
    /// the points alone once they are looked through (v1 × w2 with w2 = v2 − k v1 is v1 × v2, the
    /// k v1 × v1 cancelling) is written over the points' differences directly, and no longer waits
    /// for the temporaries (the division of k).
    /// </param>
    private static Expr? Covariant(Expr sum, IReadOnlyList<InputPoint> points, Dictionary<Expr, Scalar?>? lifts, HeldPolynomials? held)
    {
        if (points.Count < 2 || !PolynomialLifting.TryLift(sum, lifts, out var polynomial)) return null;
        if (held is not null && polynomial.Variables.Any(held.IsTemporary))
        {
            // only where that frees the sum from waiting on a temporary that holds no polynomial (the
            // quotient k), and nothing but the inputs is left: otherwise the rewrite would repeat a
            // temporary's work, or merely rearrange a sum that waits on nothing
            if (!held.WaitsOnOther(sum) || PolynomialLifting.LiftThrough(sum, held.Of) is not { } through || through.Variables.Any(held.IsTemporary)) return null;
            polynomial = through;
            sum = held.WithOwnTemporaries(sum);
        }
        if (!HasDegreeTwo(polynomial)) return null;
        var variables = polynomial.Variables;
        if (variables.Count > MaxVariables || variables.Any(v => v.StartsWith(DifferencePrefix, StringComparison.Ordinal))) return null;
        var original = Cost(sum);
        Expr? best = null;
        var bestCost = int.MaxValue;
        foreach (var layout in points.GroupBy(p => p.Layout))
        {
            var read = layout.Where(p => p.Coordinates.Any(variables.Contains)).ToList();
            if (read.Count < 2) continue;
            foreach (var anchor in read)
            {
                var substitution = new Dictionary<string, Scalar>(StringComparer.Ordinal);
                var collapse = new Dictionary<string, Scalar>(StringComparer.Ordinal);
                var differences = new Dictionary<string, (string Of, string From)>(StringComparer.Ordinal);
                foreach (var other in read.Where(p => !ReferenceEquals(p, anchor)))
                for (var i = 0; i < other.Coordinates.Count; i++)
                {
                    var (v, a) = (other.Coordinates[i], anchor.Coordinates[i]);
                    var name = $"{DifferencePrefix}{differences.Count}";
                    differences[name] = (v, a);
                    substitution[v] = Scalar.Variable(a) + Scalar.Variable(name);
                    collapse[v] = Scalar.Variable(a);
                }
                if (HasDegreeTwo(polynomial.Substitute(collapse))) continue; // products of the anchor alone would cancel
                var shifted = polynomial.Substitute(substitution);
                var lowered = ScalarLowering.Lower(shifted);
                var used = differences.Where(d => shifted.Variables.Contains(d.Key)).ToList();
                var cost = Cost(lowered);
                if (cost > original || cost >= bestCost) continue;
                bestCost = cost;
                best = BlockRewriting.Substitute(ReadingPoints(lowered, used), used.ToDictionary(d => d.Key,
                    d => ExprFactory.Difference(ExprFactory.Variable(d.Value.Of), ExprFactory.Variable(d.Value.From)), StringComparer.Ordinal));
            }
        }
        return best;
    }

    /// <summary>
    /// The lowered form with each linear sum that mixes differences and anchor coordinates written
    /// over the points themselves where that costs no more: (q − p) + 2p, the second factor of
    /// ½(q − p)·(q + p), is q + p, one addition, and ½(q − p) + p is ½(q + p), whose common ½
    /// later passes take out of the sum. A linear form loses no accuracy either way; left over
    /// the differences it costs a scaling and an addition more per coordinate.
    /// </summary>
    private static Expr ReadingPoints(Expr lowered, List<KeyValuePair<string, (string Of, string From)>> differences)
    {
        var back = differences.ToDictionary(d => d.Key, d => Scalar.Variable(d.Value.Of) - Scalar.Variable(d.Value.From), StringComparer.Ordinal);
        return BlockRewriting.ReplaceNodes(lowered, node =>
        {
            if (node is not SumExpr || !PolynomialLifting.TryLift(node, out var linear) || HasDegreeTwo(linear)) return null;
            if (!linear.Variables.Any(back.ContainsKey) || linear.Variables.All(back.ContainsKey)) return null;
            var direct = ScalarLowering.Lower(linear.Substitute(back));
            return Cost(direct) <= Cost(node) ? direct : null;
        });
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

    private static int Cost(Expr e) => CodeStatistics.CostOf(e);
}
