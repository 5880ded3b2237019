using GMac.Core.CodeGeneration;
using GMac.Core.CodeGeneration.Accuracy;
using GMac.Core.Numerics;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.Core.Tests.CodeGeneration;

/// <summary>
/// The probe shifts every input by one large common value. For vectors that makes them nearly
/// parallel, and a form that takes a cross product of two inputs loses digits there that a form
/// building on a difference (a rejection, an edge) keeps. These cases pin that the probe sees
/// that loss, and that the loss is real on inputs of the probe's kind that it never saw.
/// </summary>
public class AccuracyProbe_NearParallel
{
    private static readonly string[] Names = ["ax", "ay", "az", "bx", "by", "bz", "cx", "cy", "cz"];
    private static readonly Expr Ax = Variable("ax"), Ay = Variable("ay"), Az = Variable("az");
    private static readonly Expr Bx = Variable("bx"), By = Variable("by"), Bz = Variable("bz");
    private static readonly Expr Cx = Variable("cx"), Cy = Variable("cy"), Cz = Variable("cz");

    private static CodeBlock Block(params AssignmentStatement[] statements) =>
        new(statements, Names.ToDictionary(n => n, n => n, StringComparer.Ordinal),
            statements.Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target, StringComparer.Ordinal));

    private static AssignmentStatement Temp(string name, Expr value) => new(name, value, false);

    private static Expr Cross(Expr ux, Expr uy, Expr uz, Expr vx, Expr vy, Expr vz, int axis) => axis switch
    {
        0 => Difference(Product(uy, vz), Product(uz, vy)),
        1 => Difference(Product(uz, vx), Product(ux, vz)),
        _ => Difference(Product(ux, vy), Product(uy, vx)),
    };

    /// <summary>The part of c along n = (n1, n2, n3), after the statements that define n.</summary>
    private static AssignmentStatement[] ComponentAlongNormal(IEnumerable<AssignmentStatement> normal)
    {
        var n = new[] { Variable("n1"), Variable("n2"), Variable("n3") };
        var s = Quotient(Sum(Product(Cx, n[0]), Product(Cy, n[1]), Product(Cz, n[2])), Sum(n.Select(x => Product(x, x))));
        return [.. normal, Temp("s", s), .. n.Select((x, i) => new AssignmentStatement($"w3_{i}", Product(Variable("s"), x), true))];
    }

    /// <summary>The textbook third Gram–Schmidt vector: n = v1 × v2, 23 operations.</summary>
    private static CodeBlock FromCrossOfInputs() => Block(ComponentAlongNormal(
        Enumerable.Range(0, 3).Select(i => Temp($"n{i + 1}", Cross(Ax, Ay, Az, Bx, By, Bz, i)))));

    /// <summary>The same from the rejection w2 = v2 − (v1·v2 / v1·v1) v1: n = v1 × w2, 40 operations.</summary>
    private static CodeBlock FromRejection()
    {
        var k = Quotient(Sum(Product(Ax, Bx), Product(Ay, By), Product(Az, Bz)), Sum(Product(Ax, Ax), Product(Ay, Ay), Product(Az, Az)));
        var (qx, qy, qz) = (Variable("qx"), Variable("qy"), Variable("qz"));
        AssignmentStatement[] rejection =
        [
            Temp("k", k),
            Temp("qx", Difference(Bx, Product(Variable("k"), Ax))),
            Temp("qy", Difference(By, Product(Variable("k"), Ay))),
            Temp("qz", Difference(Bz, Product(Variable("k"), Az))),
        ];
        return Block(ComponentAlongNormal(rejection.Concat(Enumerable.Range(0, 3).Select(i => Temp($"n{i + 1}", Cross(Ax, Ay, Az, qx, qy, qz, i))))));
    }

    /// <summary>The worst normwise error against exact evaluation over vectors that share the part (shift, shift, shift).</summary>
    private static double WorstErrorWithCommonPart(CodeBlock block, double shift)
    {
        var random = new Random(23);
        var worst = 0.0;
        for (var trial = 0; trial < 30; trial++)
        {
            var inputs = Names.ToDictionary(n => n, _ => shift + random.NextDouble() * 2 - 1, StringComparer.Ordinal);
            var exact = ExactEvaluator.Evaluate(block, inputs.ToDictionary(kv => kv.Key, kv => Rational.FromDouble(kv.Value), StringComparer.Ordinal))!;
            var computed = block.Evaluate(inputs);
            var largest = exact.Values.Max(v => Math.Abs(v.ToDouble()));
            foreach (var (name, value) in exact)
                worst = Math.Max(worst, Math.Abs((Rational.FromDouble(computed[name]) - value).ToDouble()) / largest);
        }
        return worst;
    }

    [Fact]
    public void Both_forms_compute_the_same_vector()
    {
        var random = new Random(4);
        for (var trial = 0; trial < 10; trial++)
        {
            var inputs = Names.ToDictionary(n => n, _ => random.NextDouble() * 2 - 1, StringComparer.Ordinal);
            var (a, b) = (FromCrossOfInputs().Evaluate(inputs), FromRejection().Evaluate(inputs));
            foreach (var (name, value) in a)
                Assert.True(Math.Abs(value - b[name]) <= 1e-12 * Math.Max(1, Math.Abs(value)), name);
        }
        Assert.Equal(23, FromCrossOfInputs().Statistics().Operations);
        Assert.Equal(40, FromRejection().Statistics().Operations);
    }

    [Fact]
    public void On_nearly_parallel_vectors_the_cross_product_of_the_inputs_loses_digits_that_the_rejection_keeps()
    {
        // well conditioned, the two are alike; with a common part of 1e3 (not the probe's 1e4) they are not
        Assert.InRange(WorstErrorWithCommonPart(FromCrossOfInputs(), 0), 0, 1e-12);
        Assert.InRange(WorstErrorWithCommonPart(FromRejection(), 0), 0, 1e-12);
        var textbook = WorstErrorWithCommonPart(FromCrossOfInputs(), 1e3);
        var rejection = WorstErrorWithCommonPart(FromRejection(), 1e3);
        Assert.True(textbook > 100 * rejection, $"cross product of the inputs {textbook:e2}, from the rejection {rejection:e2}");
    }

    [Fact]
    public void The_probe_pays_for_the_form_that_keeps_them_and_takes_the_cheaper_one_where_nothing_is_lost()
    {
        Assert.True(AccuracyProbe.Error(FromCrossOfInputs()) > AccuracyProbe.Factor * AccuracyProbe.Error(FromRejection()));
        Assert.Equal(1, AccuracyProbe.MostAccurateAffordable([FromCrossOfInputs(), FromRejection()]));
        // the rejection computed twice over is no more accurate than once: the cheaper stays
        Assert.Equal(0, AccuracyProbe.MostAccurateAffordable([FromRejection(), FromRejection()]));
    }
}
