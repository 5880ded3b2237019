using System.Runtime.CompilerServices;
using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Before lowering, tries substituting each temporary into its readers at the symbolic level,
/// where the canonical form merges like terms and cancels (unlike a tree substitution), and keeps
/// the substitution when the readers then cost no more than the temporary and the readers did.
/// Costs are measured on the lowered (factored) trees, so the choice follows real operation counts.
/// </summary>
internal static class SymbolicInliner
{
    public sealed class Assignment(string name, Scalar value, bool isOutput)
    {
        public string Name { get; } = name;
        public Scalar Value { get; set; } = value;
        public bool IsOutput { get; } = isOutput;
    }

    /// <summary>
    /// Past this many assignments each trial (substitute, simplify, lower every reader) is repeated
    /// for every pair of temporary and reader, which grows too fast for large frames; the block is
    /// then left to the optimizer's own passes.
    /// </summary>
    public const int MaxAssignments = 400;

    public static void Inline(List<Assignment> assignments, Func<Scalar, Scalar> simplify, int maxRounds = 4)
    {
        if (assignments.Count > MaxAssignments) return;
        // What each refused temporary and its readers were when it was refused: the trial is a
        // function of exactly these values (scalars are hash-consed, so identity is equality), and
        // a later round repeats it only for temporaries whose neighbourhood changed since.
        var refused = new Dictionary<Assignment, Scalar[]>(ReferenceEqualityComparer.Instance);
        for (var round = 0; round < maxRounds; round++)
        {
            var changed = false;
            for (var i = 0; i < assignments.Count; i++)
            {
                var temp = assignments[i];
                if (temp.IsOutput) continue;
                var readers = assignments.Where(a => a.Value.Variables.Contains(temp.Name)).ToList();
                if (readers.Count == 0) continue;
                var neighbourhood = readers.Select(r => r.Value).Prepend(temp.Value).ToArray();
                if (refused.TryGetValue(temp, out var before) && before.AsSpan().SequenceEqual(neighbourhood)) continue;
                var replacement = new Dictionary<string, Scalar>(StringComparer.Ordinal) { [temp.Name] = temp.Value };
                var keep = Cost(temp.Value) + readers.Sum(r => Cost(r.Value));
                // Costs are never negative: once the readers substituted so far cost more than
                // keeping the temporary, the rest need not be simplified to refuse it.
                var substituted = new List<Scalar>(readers.Count);
                var inline = 0;
                foreach (var r in readers)
                {
                    substituted.Add(simplify(r.Value.Substitute(replacement)));
                    inline += Cost(substituted[^1]);
                    if (inline > keep) break;
                }
                if (inline > keep)
                {
                    refused[temp] = neighbourhood;
                    continue;
                }
                for (var k = 0; k < readers.Count; k++) readers[k].Value = substituted[k];
                assignments.RemoveAt(i);
                i--;
                changed = true;
            }
            if (!changed) break;
        }
    }

    /// <summary>
    /// Operations of a scalar once lowered (factored), remembered per scalar for the process:
    /// lowering depends on nothing else, and every form and binding point asks about the same values.
    /// </summary>
    private static int Cost(Scalar s) =>
        Costs.GetValue(s, static s => new StrongBox<int>(CodeStatistics.CostOf(ScalarLowering.Lower(s)))).Value;

    private static readonly ConditionalWeakTable<Scalar, StrongBox<int>> Costs = new();
}
