using GMac.Core.CodeGeneration;
using GMac.Core.Numerics;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

public class OriginShift_Laws
{
    private static readonly string[] Inputs = ["ax", "ay", "az", "bx", "by", "bz"];
    private static readonly string[] Axes = ["x", "y", "z"];

    private static Expr V(string n) => Variable(n);

    private static CodeBlock Block(params (string Name, Expr Value)[] outputs) =>
        new(outputs.Select(o => new AssignmentStatement(o.Name, o.Value, true)),
            Inputs.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            outputs.ToDictionary(o => o.Name, o => o.Name, StringComparer.Ordinal))
        {
            Points = [new InputPoint("p", ["ax", "ay", "az"], IsPosition: true), new InputPoint("p", ["bx", "by", "bz"], IsPosition: true)],
        };

    /// <summary>The conformal point no + m + ½|m|² ni of the midpoint m of a and b, from absolute coordinates.</summary>
    private static CodeBlock Midpoint()
    {
        var half = Constant(new Rational(1, 2));
        var m = Axes.Select(c => Product(half, Sum(V("a" + c), V("b" + c)))).ToArray();
        return Block(("no", Constant(1)), ("ex", m[0]), ("ey", m[1]), ("ez", m[2]),
            ("ni", Product(half, Sum(m.Select(x => Product(x, x))))));
    }

    private static Dictionary<string, double> RandomInputs(Random random, double offset) =>
        Inputs.ToDictionary(n => n, _ => offset + random.NextDouble(), StringComparer.Ordinal);

    [Fact]
    public void Moved_outputs_agree_with_the_block_and_the_quadratic_one_reuses_the_moved_vector()
    {
        var block = Midpoint();
        var law = OriginShift.Find(block);
        Assert.NotNull(law);
        var shifted = OriginShift.Apply(block, law);
        // ni = ni′ + a·e′ + ½ no′|a|² is written ½ a·(e′ + e) + ni′ over the moved e, not from |a|²
        var ni = shifted.Outputs.Single(o => o.Target == "ni").Value;
        Assert.Contains(ni.DescendantsAndSelf().OfType<VariableExpr>(), v => v.Name.StartsWith("__gmac_shift_t", StringComparison.Ordinal));
        var reduced = Optimizer.Reduce(shifted);
        var random = new Random(11);
        for (var i = 0; i < 20; i++)
        {
            var x = RandomInputs(random, i % 2 == 0 ? 0 : -3);
            var expected = block.Evaluate(x);
            foreach (var b in new[] { shifted, reduced })
            foreach (var (name, value) in b.Evaluate(x))
                Assert.Equal(expected[name], value, 1e-12 * (1 + Math.Abs(expected[name])));
        }
    }

    [Fact]
    public void Moment_of_a_line_moves_linearly_and_keeps_its_digits_far_from_the_origin()
    {
        // d = b − a stays, the moment a × b = a × d′ moves with a: over the differences it keeps
        // its digits where a and b are 1e5 from the origin and 1e-3 apart.
        var cross = new (string, Expr)[]
        {
            ("mx", Difference(Product(V("ay"), V("bz")), Product(V("az"), V("by")))),
            ("my", Difference(Product(V("az"), V("bx")), Product(V("ax"), V("bz")))),
            ("mz", Difference(Product(V("ax"), V("by")), Product(V("ay"), V("bx")))),
        };
        var block = Block([.. Axes.Select(c => ("d" + c, Difference(V("b" + c), V("a" + c)))), .. cross]);
        var law = OriginShift.Find(block);
        Assert.NotNull(law);
        var shifted = Optimizer.Reduce(OriginShift.Apply(block, law));
        var random = new Random(3);
        for (var i = 0; i < 20; i++)
        {
            var a = Axes.Select(_ => 1e5 * (1 + random.NextDouble())).ToArray();
            var d = Axes.Select(_ => 1e-3 * (random.NextDouble() - 0.5)).ToArray();
            var x = new Dictionary<string, double>(StringComparer.Ordinal);
            for (var c = 0; c < 3; c++) (x["a" + Axes[c]], x["b" + Axes[c]]) = (a[c], a[c] + d[c]);
            var db = Axes.Select((c, k) => x["b" + c] - x["a" + c]).ToArray(); // the differences as the inputs hold them
            var exact = new[] { a[1] * db[2] - a[2] * db[1], a[2] * db[0] - a[0] * db[2], a[0] * db[1] - a[1] * db[0] };
            var values = shifted.Evaluate(x);
            var scale = exact.Max(Math.Abs);
            for (var c = 0; c < 3; c++) Assert.Equal(exact[c], values["m" + Axes[c]], 1e-13 * scale);
        }
    }

    [Fact]
    public void Outputs_that_do_not_move_with_the_points_have_no_law()
    {
        // a.x b.x changes with a translation but not as a combination of its value at the origin (zero)
        Assert.Null(OriginShift.Find(Block(("p", Product(V("ax"), V("bx"))))));
        // |b − a|² does not move at all: the translation-invariance pass's work, not this one's
        Assert.Null(OriginShift.Find(Block(("s", Sum(Axes.Select(c => Product(Difference(V("b" + c), V("a" + c)), Difference(V("b" + c), V("a" + c)))))))));
        // a quotient is not a polynomial
        Assert.Null(OriginShift.Find(Block(("q", Quotient(V("bx"), Sum(V("ax"), Constant(2)))))));
    }
}
