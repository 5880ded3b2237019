namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Places signs so that the code computes fewer negations (each one a sign-mask instruction the
/// compiler keeps), without changing any operation count or any computed bit (but the sign of an
/// exact zero, see <see cref="SignedForm"/>). A temporary may
/// hold its value negated, when the statements that read it then absorb the sign into a
/// subtraction, a swapped difference or a constant; e.g. t = a·b − c·d read as −(t·x) and −(t·y)
/// becomes t = c·d − a·b read as t·x and t·y. Temporaries are flipped one at a time, each kept
/// when it lowers the block's count of negations, until no flip helps. Statements untouched by a
/// flip keep their text unless their own signs can be placed better.
/// </summary>
public sealed class SignPlacementPass : IOptimizerPass
{
    private const int MaxRounds = 4;

    public string Name => "sign placement";

    public CodeBlock Run(CodeBlock block)
    {
        var statements = block.Statements;
        var definitions = new Dictionary<string, int>(StringComparer.Ordinal);
        var assignedTwice = new HashSet<string>(StringComparer.Ordinal);
        for (var i = 0; i < statements.Count; i++)
            if (statements[i] is AssignmentStatement { IsOutput: false } t && !definitions.TryAdd(t.Target, i))
                assignedTwice.Add(t.Target);
        var flipped = new HashSet<string>(StringComparer.Ordinal);
        bool IsFlipped(string name) => flipped.Contains(name);
        void Toggle(string name)
        {
            if (!flipped.Remove(name)) flipped.Add(name);
        }
        int Cost(int i)
        {
            var negative = statements[i] is AssignmentStatement { IsOutput: false } t && IsFlipped(t.Target);
            var cost = 0;
            foreach (var e in statements[i].Expressions) cost += SignCost.Of(e, negative, IsFlipped);
            return cost;
        }
        var costs = new int[statements.Count];
        for (var i = 0; i < costs.Length; i++) costs[i] = Cost(i);
        var readers = costs.Any(c => c > 0) ? Readers(statements, definitions, assignedTwice) : [];

        for (var round = 0; round < MaxRounds && readers.Count > 0; round++)
        {
            var improved = false;
            foreach (var (name, affected) in readers)
            {
                if (affected.All(i => costs[i] == 0)) continue; // no negation there to save
                Toggle(name);
                var newCosts = affected.Select(Cost).ToArray();
                var gain = affected.Select((i, k) => costs[i] - newCosts[k]).Sum();
                if (gain > 0 && newCosts.All(c => c < SignedForm.Unprintable))
                {
                    for (var k = 0; k < affected.Length; k++) costs[affected[k]] = newCosts[k];
                    improved = true;
                }
                else Toggle(name);
            }
            if (!improved) break;
        }

        var touched = readers.Where(r => flipped.Contains(r.Name)).SelectMany(r => r.Statements).ToHashSet();
        var changed = false;
        var result = statements.Select((s, i) =>
        {
            if (!touched.Contains(i) && costs[i] >= s.Expressions.Sum(SignedForm.PrintedNegations)) return s;
            changed = true;
            return Rewrite(s, IsFlipped).Statement;
        }).ToArray();
        return changed ? block.WithStatements(result) : block;
    }

    /// <summary>
    /// The temporaries that may be flipped, in order, each with its own statement and those that
    /// read it. A temporary holding a call stays as it is: negating it would cost a negation anyway,
    /// and the emitter pairs a sine and a cosine temporary into one Math.SinCos.
    /// </summary>
    private static List<(string Name, int[] Statements)> Readers(IReadOnlyList<CodeStatement> statements, Dictionary<string, int> definitions, HashSet<string> assignedTwice)
    {
        var readers = new Dictionary<string, List<int>>(StringComparer.Ordinal);
        foreach (var (name, i) in definitions)
            if (!assignedTwice.Contains(name) && ((AssignmentStatement)statements[i]).Value is not CallExpr) readers[name] = [i];
        var names = new HashSet<string>(StringComparer.Ordinal);
        for (var i = 0; i < statements.Count; i++)
        {
            names.Clear();
            foreach (var e in statements[i].Expressions) CollectVariables(e, names);
            foreach (var name in names)
                if (readers.TryGetValue(name, out var list) && list[^1] != i) list.Add(i);
        }
        return readers.OrderBy(r => r.Value[0]).Select(r => (r.Key, r.Value.ToArray())).ToList();
    }

    private static void CollectVariables(Expr e, HashSet<string> names)
    {
        if (e is VariableExpr v) names.Add(v.Name);
        foreach (var c in e.Children) CollectVariables(c, names);
    }

    /// <summary>A statement with its signs placed for the chosen flips, and the negations it then needs.</summary>
    private static (CodeStatement Statement, int Cost) Rewrite(CodeStatement s, Func<string, bool> isFlipped)
    {
        var negateResult = s is AssignmentStatement { IsOutput: false } t && isFlipped(t.Target);
        var placed = s.Expressions.Select(e => SignedForm.Materialize(SignedForm.Of(e, isFlipped), negateResult)).ToArray();
        return (s.WithExpressions(placed.Select(p => p.Value).ToArray()), placed.Sum(p => p.Cost));
    }
}
