using GMac.Core.CodeGeneration;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>The allocation-free walk and children view against a plain recursive walk of random trees.</summary>
public class ExprWalk_Order
{
    private static Expr RandomTree(Random random, int depth)
    {
        if (depth == 0 || random.Next(4) == 0)
            return random.Next(3) == 0 ? new ConstantExpr(random.Next(2, 9)) : new VariableExpr($"v{random.Next(6)}");
        return random.Next(6) switch
        {
            0 => new NegateExpr(RandomTree(random, depth - 1)),
            1 => new QuotientExpr(RandomTree(random, depth - 1), RandomTree(random, depth - 1)),
            2 => new PowerExpr(RandomTree(random, depth - 1), random.Next(2, 4)),
            3 => new CallExpr("sin", [RandomTree(random, depth - 1)]),
            // wide nodes, so the walk's stack outgrows its first size
            4 => new SumExpr(Enumerable.Range(0, random.Next(2, 24)).Select(_ => RandomTree(random, depth - 1)).ToArray()),
            _ => new ProductExpr(Enumerable.Range(0, random.Next(2, 12)).Select(_ => RandomTree(random, depth - 1)).ToArray()),
        };
    }

    /// <summary>Parents before children, the last child first.</summary>
    private static void Reference(Expr e, List<Expr> into)
    {
        into.Add(e);
        var children = new List<Expr>();
        foreach (var c in (IEnumerable<Expr>)e.Children) children.Add(c);
        for (var i = children.Count - 1; i >= 0; i--) Reference(children[i], into);
    }

    [Fact]
    public void Foreach_and_linq_walks_visit_the_nodes_of_the_recursive_walk_in_its_order()
    {
        var random = new Random(3);
        for (var trial = 0; trial < 200; trial++)
        {
            var tree = RandomTree(random, 4);
            var expected = new List<Expr>();
            Reference(tree, expected);

            var walked = new List<Expr>();
            foreach (var node in tree.DescendantsAndSelf()) walked.Add(node);
            Assert.Equal(expected.Count, walked.Count);
            for (var i = 0; i < expected.Count; i++) Assert.Same(expected[i], walked[i]);
            Assert.Equal(expected, tree.DescendantsAndSelf().Select(n => n)); // the boxed walk LINQ uses
            Assert.Equal(expected.Count, tree.Size);
        }
    }

    [Fact]
    public void Children_are_the_constructor_arguments_in_order()
    {
        Expr a = Variable("a"), b = Variable("b"), c = Variable("c");
        var sum = new SumExpr([a, b, c]);
        Assert.Equal([a, b, c], sum.Children.ToArray());
        Assert.Equal(3, sum.Children.Count);
        Assert.Same(b, sum.Children[1]);
        Assert.Equal([a, b], new QuotientExpr(a, b).Children.ToArray());
        Assert.Empty(a.Children);
        Assert.True(a.IsLeaf);
        Assert.Equal(sum, new SumExpr([a, b, c]));
        Assert.NotEqual(sum, new SumExpr([a, c, b]));
    }

    [Fact]
    public void A_sum_drops_pairs_of_opposite_terms_wherever_they_stand()
    {
        Expr a = Variable("a"), b = Variable("b"), c = Variable("c");
        Assert.Equal(c, Sum(a, Negate(b), c, b, Negate(a)));
        Assert.Equal(ConstantExpr.Zero, Sum(Negate(a), a));
        Assert.Equal(Sum(a, a), Sum(a, a, b, Negate(b)));
        Assert.Equal(Sum(a, Negate(Product(b, c))), Sum(Product(c, b), a, Negate(Product(b, c)), Negate(Product(c, b))));
    }
}
