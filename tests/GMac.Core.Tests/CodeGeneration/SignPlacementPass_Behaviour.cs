using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Passes;
using static GMac.Core.CodeGeneration.ExprFactory;
using static GMac.Core.Tests.CodeGeneration.PassTestBlocks;

namespace GMac.Core.Tests.CodeGeneration;

public class SignPlacementPass_Behaviour
{
    private static readonly Expr T = Variable("t"), U = Variable("u");

    /// <summary>t = a·b − c·d, then o1 = −(t·c), o2 = −(t·d): two negations of one temporary's products.</summary>
    private static CodeBlock NegatedReads() => Block(
        Temp("t", Difference(Product(A, B), Product(C, D))),
        Out("o1", Negate(Product(T, C))),
        Out("o2", Negate(Product(T, D))));

    [Fact]
    public void A_temporary_read_twice_under_a_negation_holds_the_swapped_difference_and_no_negation_is_left()
    {
        var before = NegatedReads();
        var after = new SignPlacementPass().Run(before);
        Assert.Equal("temp t = c * d - a * b;\no1 = t * c;\no2 = t * d;", Text(after));
        Assert.Equal(2, NegationsInText(before));
        Assert.Equal(0, NegationsInText(after));
        AssertSameOperations(before, after);
        AssertBitIdenticalOutputs(before, after);
    }

    [Fact]
    public void A_negated_sum_of_negated_products_becomes_a_plain_sum()
    {
        // −a·(−b − c) is a·(b + c): the negation inside the factor and the one in front cancel
        var before = Block(Out("o", Sum(D, Negate(Product(A, Sum(Negate(B), Negate(C)))))));
        var after = new SignPlacementPass().Run(before);
        Assert.Equal(1, NegationsInText(before));
        Assert.Equal(0, NegationsInText(after));
        Assert.Equal("o = d + a * (b + c);", Text(after));
        AssertBitIdenticalOutputs(before, after);
    }

    [Fact]
    public void A_cross_product_read_by_a_triple_product_and_its_negated_multiples_keeps_one_negation_at_most()
    {
        // Gram-Schmidt by contractions: n = a × b (as three differences), det = n·c, outputs n × a and −det n
        var (ax, ay, az, bx, by, bz, cx, cy, cz) = (A, B, C, D, Variable("e"), Variable("f"), Variable("g"), Variable("h"), Variable("i"));
        Expr t0 = Variable("t0"), t1 = Variable("t1"), t2 = Variable("t2"), t3 = Variable("t3");
        var before = new CodeBlock(
            [
            Temp("t0", Difference(Product(ax, by), Product(ay, bx))),
            Temp("t1", Difference(Product(ax, bz), Product(az, bx))),
            Temp("t2", Difference(Product(ay, bz), Product(az, by))),
            Temp("t3", Sum(Product(t0, cz), Product(t2, cx), Negate(Product(t1, cy)))),
            Out("w1", Sum(Negate(Product(t0, ay)), Negate(Product(t1, az)))),
            Out("w2", Difference(Product(t0, ax), Product(t2, az))),
            Out("w3", Sum(Product(t1, ax), Product(t2, ay))),
            Out("w4", Negate(Product(t2, t3))),
            Out("w5", Product(t1, t3)),
            Out("w6", Negate(Product(t0, t3))),
            ],
            "abcdefghi".ToDictionary(k => k.ToString(), k => k.ToString(), StringComparer.Ordinal),
            Enumerable.Range(1, 6).ToDictionary(k => $"w{k}", k => $"w{k}", StringComparer.Ordinal));
        var after = new SignPlacementPass().Run(before);
        Assert.Equal(3, NegationsInText(before));
        Assert.True(NegationsInText(after) <= 1, Text(after));
        AssertSameOperations(before, after);
        AssertBitIdenticalOutputs(before, after);
    }

    [Fact]
    public void A_block_whose_signs_cannot_be_placed_better_is_returned_unchanged()
    {
        // o1 needs its negation whatever t holds; flipping t would move it to o2
        var before = Block(
            Temp("t", Product(A, B)),
            Out("o1", Negate(Product(T, C))),
            Out("o2", Sum(Product(T, D), C)),
            Out("o3", Difference(A, Call("sqrt", B))));
        Assert.Same(before, new SignPlacementPass().Run(before));
    }

    [Fact]
    public void A_sine_temporary_keeps_its_value_so_the_emitter_can_still_pair_it_with_the_cosine()
    {
        var before = Block(
            Temp("s", Call("sin", A)),
            Temp("u", Call("cos", A)),
            Out("o1", Negate(Product(Variable("s"), B))),
            Out("o2", Negate(Product(Variable("s"), C))),
            Out("o3", Product(U, D)));
        var after = new SignPlacementPass().Run(before);
        Assert.Equal(before.Temporaries, after.Temporaries);
        // both calls stay whole temporaries, which the emitter computes together
        Assert.Contains("s = sin(a);", BlockText.Of(after));
        Assert.Contains("u = cos(a);", BlockText.Of(after));
    }

    [Fact]
    public void Random_blocks_keep_every_output_bit_for_bit_and_their_operation_counts()
    {
        var random = new Random(14);
        for (var n = 0; n < 100; n++)
        {
            var before = RandomBlock(random);
            var after = new SignPlacementPass().Run(before);
            AssertSameOperations(before, after);
            AssertBitIdenticalOutputs(before, after);
            Assert.True(NegationsInText(after) <= NegationsInText(before));
        }
    }

    [Fact]
    public void The_search_counts_the_negations_of_the_statements_it_would_build()
    {
        var random = new Random(15);
        for (var n = 0; n < 100; n++)
        {
            var block = RandomBlock(random);
            var flipped = block.Temporaries.Select(t => t.Target).Where(_ => random.Next(2) == 0).ToHashSet();
            foreach (var e in block.Statements.SelectMany(s => s.Expressions))
            foreach (var negative in new[] { false, true })
            {
                var built = SignedForm.Materialize(SignedForm.Of(e, flipped.Contains), negative).Cost;
                if (built < SignedForm.Unprintable) Assert.Equal(built, SignCost.Of(e, negative, flipped.Contains));
            }
        }
    }

    /// <summary>Temporaries and outputs over a, b, c, d and earlier temporaries, with random signs and shapes.</summary>
    private static CodeBlock RandomBlock(Random random)
    {
        var names = new List<Expr> { A, B, C, D };
        var statements = new List<CodeStatement>();
        Expr Leaf() => random.Next(8) == 0 ? Constant(random.Next(2, 5) * (random.Next(2) == 0 ? -1 : 1)) : names[random.Next(names.Count)];
        Expr Node(int depth)
        {
            if (depth == 0) return Leaf();
            var e = random.Next(5) switch
            {
                0 => Sum(Enumerable.Range(0, random.Next(2, 5)).Select(_ => Node(depth - 1))),
                1 => Product(Node(depth - 1), Node(depth - 1)),
                2 => Difference(Node(depth - 1), Node(depth - 1)),
                3 => Quotient(Node(depth - 1), Sum(Node(depth - 1), Constant(7))),
                _ => Leaf(),
            };
            return random.Next(3) == 0 ? Negate(e) : e;
        }
        for (var i = 0; i < 6; i++)
        {
            statements.Add(Temp($"t{i}", Node(2)));
            names.Add(Variable($"t{i}"));
        }
        for (var i = 0; i < 4; i++) statements.Add(Out($"o{i}", Node(2)));
        return Block(statements.ToArray());
    }

    private static string Text(CodeBlock block) => block.ToString().ReplaceLineEndings("\n");

    /// <summary>Sign-mask instructions the printed code needs: a negation outside a subtraction, or a sum of negated terms only.</summary>
    private static int NegationsInText(CodeBlock block)
    {
        var text = BlockText.Of(block);
        return text.Split('\n').Sum(line => line.Split(" = ", 2) is [_, var rhs] ? CountUnaryMinus(rhs) : 0);
    }

    private static int CountUnaryMinus(string text)
    {
        var count = 0;
        for (var i = 0; i < text.Length; i++)
        {
            if (text[i] != '-') continue;
            var j = i - 1;
            while (j >= 0 && text[j] == ' ') j--;
            var unary = j < 0 || text[j] is '(' or '*' or '/' or '+' or '-' or ',';
            var literal = i + 1 < text.Length && char.IsDigit(text[i + 1]);
            if (unary && !literal) count++;
        }
        return count;
    }

    private static void AssertSameOperations(CodeBlock before, CodeBlock after)
    {
        var (b, a) = (before.Statistics(), after.Statistics());
        Assert.Equal((b.Additions, b.Multiplications, b.Divisions, b.Calls, b.Temporaries), (a.Additions, a.Multiplications, a.Divisions, a.Calls, a.Temporaries));
    }

    /// <summary>
    /// Evaluates both blocks as their C# text does (a sum's positive terms first) and compares the bits;
    /// an exact zero may change sign, since b − a is +0 where −(a − b) is −0.
    /// </summary>
    private static void AssertBitIdenticalOutputs(CodeBlock before, CodeBlock after)
    {
        var random = new Random(30);
        for (var i = 0; i < 20; i++)
        {
            var inputs = new[] { "a", "b", "c", "d", "e", "f", "g", "h", "i" }.ToDictionary(k => k, _ => random.NextDouble() * 20 - 10, StringComparer.Ordinal);
            var expected = PrintedOrder.Evaluate(before, inputs);
            var actual = PrintedOrder.Evaluate(after, inputs);
            foreach (var (k, v) in expected)
                if (!v.Equals(actual[k]))
                    Assert.Fail($"{k}: {v:R} before, {actual[k]:R} after\n{Text(before)}\n---\n{Text(after)}");
        }
    }
}
