using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using GMac.Core.Symbolic;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// Work the optimizer keeps between steps instead of redoing it (key counts of common-subexpression
/// elimination, lifts and group searches of the translation-invariance pass, refused trials of the
/// symbolic inliner) must give what redoing it from scratch gives.
/// </summary>
public class IncrementalCounting_Behaviour
{
    private static readonly Expr[] Leaves = [A, B, C, D, Constant(2), Constant(3)];

    /// <summary>A random tree over few leaves and shallow depth, so that subtrees repeat often.</summary>
    private static Expr RandomExpr(Random random, int depth)
    {
        if (depth == 0 || random.Next(4) == 0) return Leaves[random.Next(Leaves.Length)];
        var arity = random.Next(2, 4);
        var children = Enumerable.Range(0, arity).Select(_ => RandomExpr(random, depth - 1)).ToArray();
        return random.Next(5) switch
        {
            0 => Negate(Sum(children)),
            1 or 2 => Sum(children),
            _ => Product(children),
        };
    }

    private static CodeBlock RandomBlock(Random random)
    {
        var statements = Enumerable.Range(0, random.Next(2, 7)).Select(i => Out($"o{i}", RandomExpr(random, 4))).ToArray();
        return Block(statements);
    }

    [Fact]
    public void Common_subexpression_counts_kept_through_extractions_equal_a_recount_of_the_result()
    {
        var random = new Random(14);
        for (var trial = 0; trial < 200; trial++)
        {
            var block = RandomBlock(random);
            var pass = new CommonSubexpressionPass();
            var result = pass.Run(block, out var kept);
            var recount = new CommonSubexpressionPass.KeyCounts();
            foreach (var s in result.Statements) recount.Add(pass.Counted(s).Keys, +1);
            Assert.Equal(recount.Totals.OrderBy(kv => kv.Key.ToString()).Select(kv => (kv.Key.ToString(), kv.Value)),
                kept.Totals.OrderBy(kv => kv.Key.ToString()).Select(kv => (kv.Key.ToString(), kv.Value)));
            Assert.Equal(recount.Repeated.Select(k => k.ToString()).Order(), kept.Repeated.Select(k => k.ToString()).Order());
            AssertSameOutputs(block, result);
        }
    }

    [Fact]
    public void Common_subexpression_elimination_leaves_no_repeated_operation()
    {
        var random = new Random(15);
        for (var trial = 0; trial < 100; trial++)
        {
            var result = new CommonSubexpressionPass().Run(RandomBlock(random));
            var fresh = new CommonSubexpressionPass();
            var counts = new CommonSubexpressionPass.KeyCounts();
            foreach (var s in result.Statements) counts.Add(fresh.Counted(s).Keys, +1);
            // every non-leaf key costs at least one operation, so a repeated one would have been extracted
            Assert.Empty(counts.Repeated);
        }
    }

    [Fact]
    public void Pair_counts_merged_from_remembered_statements_equal_one_walk_over_the_whole_block()
    {
        var random = new Random(18);
        var pass = new PairExtractionPass(); // one instance: its remembered statements carry over between trials
        var previous = RandomBlock(random);
        for (var trial = 0; trial < 200; trial++)
        {
            // half the statements come from the previous block, as after an extraction that left them alone
            var kept = previous.Statements.Where(_ => random.Next(2) == 0).ToList();
            var fresh = RandomBlock(random).Statements.Select((s, i) => Out($"n{trial}_{i}", ((AssignmentStatement)s).Value));
            var block = Block(kept.Concat(fresh).ToArray());
            var whole = block.WithStatements([new VerbatimStatement(block.Statements.SelectMany(s => s.Expressions).Select(VerbatimPart.Expression).ToArray())]);
            Assert.Equal(new PairExtractionPass().FindBest(whole), pass.FindBest(block));
            AssertSameOutputs(block, pass.Run(block));
            previous = block;
        }
    }

    [Fact]
    public void Lifting_with_remembered_subtrees_gives_the_polynomial_lifted_afresh()
    {
        var random = new Random(16);
        var known = new Dictionary<Expr, Scalar?>(ReferenceEqualityComparer.Instance);
        for (var trial = 0; trial < 200; trial++)
        {
            var e = RandomExpr(random, 4);
            foreach (var node in e.DescendantsAndSelf())
            {
                var fresh = PolynomialLifting.TryLift(node, out var expected);
                Assert.Equal(fresh, PolynomialLifting.TryLift(node, known, out var remembered));
                if (fresh) Assert.Same(expected, remembered);
            }
        }
    }

    [Fact]
    public void The_symbolic_inliner_ends_where_retrying_every_temporary_every_round_ends()
    {
        var random = new Random(17);
        var inputs = new[] { "a", "b", "c" }.Select(Scalar.Variable).ToArray();
        for (var trial = 0; trial < 60; trial++)
        {
            var assignments = new List<(string Name, Scalar Value, bool IsOutput)>();
            var count = random.Next(3, 9);
            for (var i = 0; i < count; i++)
            {
                var readable = inputs.Concat(assignments.Where(a => !a.IsOutput).Select(a => Scalar.Variable(a.Name))).ToArray();
                Scalar Pick() => readable[random.Next(readable.Length)];
                var value = random.Next(3) switch
                {
                    0 => Pick() * Pick() + Pick(),
                    1 => (Pick() - Pick()) * Pick(),
                    _ => Pick() + Pick() * Scalar.Constant(2),
                };
                assignments.Add(($"t{i}", value, i == count - 1 || random.Next(4) == 0));
            }
            var actual = assignments.Select(a => new SymbolicInliner.Assignment(a.Name, a.Value, a.IsOutput)).ToList();
            SymbolicInliner.Inline(actual, s => s);
            var expected = assignments.Select(a => new SymbolicInliner.Assignment(a.Name, a.Value, a.IsOutput)).ToList();
            InlineRetryingEverything(expected);
            Assert.Equal(expected.Select(a => (a.Name, a.Value.ToString())), actual.Select(a => (a.Name, a.Value.ToString())));
        }
    }

    /// <summary>The inliner's rule applied naively: every temporary tried again in every round.</summary>
    private static void InlineRetryingEverything(List<SymbolicInliner.Assignment> assignments)
    {
        static int Cost(Scalar s) =>
            new CodeBlock([new AssignmentStatement("x", ScalarLowering.Lower(s), true)], new Dictionary<string, string>(), new Dictionary<string, string>()).Statistics().Cost;
        for (var round = 0; round < 4; round++)
        {
            var changed = false;
            for (var i = 0; i < assignments.Count; i++)
            {
                var temp = assignments[i];
                if (temp.IsOutput) continue;
                var readers = assignments.Where(a => a.Value.Variables.Contains(temp.Name)).ToList();
                if (readers.Count == 0) continue;
                var substituted = readers.Select(r => r.Value.Substitute(temp.Name, temp.Value)).ToList();
                if (substituted.Sum(Cost) > Cost(temp.Value) + readers.Sum(r => Cost(r.Value))) continue;
                for (var k = 0; k < readers.Count; k++) readers[k].Value = substituted[k];
                assignments.RemoveAt(i);
                i--;
                changed = true;
            }
            if (!changed) break;
        }
    }
}
