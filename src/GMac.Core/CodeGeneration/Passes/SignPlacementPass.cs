namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Places signs so that the code computes fewer negations (each one a sign-mask instruction the
/// compiler keeps), without changing any operation count or any computed bit. A temporary may
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
        // A sine or cosine temporary stays as it is: the emitter pairs those into one Math.SinCos.
        var candidates = definitions.Where(d => !assignedTwice.Contains(d.Key) && ((AssignmentStatement)statements[d.Value]).Value is not CallExpr)
            .OrderBy(d => d.Value).Select(d => d.Key).ToList();
        var readers = candidates.ToDictionary(c => c, _ => new List<int>(), StringComparer.Ordinal);
        for (var i = 0; i < statements.Count; i++)
        foreach (var name in statements[i].Expressions.SelectMany(e => e.DescendantsAndSelf()).OfType<VariableExpr>().Select(v => v.Name).Distinct())
            if (readers.TryGetValue(name, out var list)) list.Add(i);

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
        var costs = Enumerable.Range(0, statements.Count).Select(Cost).ToArray();

        for (var round = 0; round < MaxRounds; round++)
        {
            var improved = false;
            foreach (var name in candidates)
            {
                var affected = readers[name].Append(definitions[name]).Distinct().ToArray();
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

        var touched = flipped.SelectMany(n => readers[n].Append(definitions[n])).ToHashSet();
        var changed = false;
        var result = statements.Select((s, i) =>
        {
            if (!touched.Contains(i) && costs[i] >= s.Expressions.Sum(SignedForm.PrintedNegations)) return s;
            changed = true;
            return Rewrite(s, IsFlipped).Statement;
        }).ToArray();
        return changed ? block.WithStatements(result) : block;
    }

    /// <summary>A statement with its signs placed for the chosen flips, and the negations it then needs.</summary>
    private static (CodeStatement Statement, int Cost) Rewrite(CodeStatement s, Func<string, bool> isFlipped)
    {
        var negateResult = s is AssignmentStatement { IsOutput: false } t && isFlipped(t.Target);
        var placed = s.Expressions.Select(e => SignedForm.Materialize(SignedForm.Of(e, isFlipped), negateResult)).ToArray();
        return (s.WithExpressions(placed.Select(p => p.Value).ToArray()), placed.Sum(p => p.Cost));
    }
}
