using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

/// <summary>
/// Outputs whose targets may be inputs read after them (here all of <c>v</c>) either wait until
/// the last read, or the inputs read after them are read into locals where first needed and every
/// output is written once the inputs it may overwrite have been read: the second, except in code
/// that calls math functions where it takes more locals. A held output whose value a temporary already holds is written from that
/// temporary: a second local holding a copy is code the hand writer would not write.
/// </summary>
public class CSharpEmitter_HeldOutputs
{
    private static CodeBlock Block(params CodeStatement[] statements)
    {
        var inputs = new Dictionary<string, string> { ["a"] = "v.a", ["b"] = "v.b", ["c"] = "v.c" };
        var targets = statements.OfType<AssignmentStatement>().Where(s => s.IsOutput)
            .ToDictionary(s => s.Target, s => "v." + s.Target, StringComparer.Ordinal);
        return new CodeBlock(statements, inputs, targets);
    }

    private static readonly CodeStatement Difference = new AssignmentStatement("d", ExprFactory.Difference(Variable("b"), Variable("a")), false);

    [Fact]
    public void Outputs_that_are_a_temporary_or_its_negation_wait_for_the_last_read_without_a_local_of_their_own()
    {
        // two outputs written early, three inputs read after them, and a call: holding the outputs takes fewer locals
        var code = CSharpEmitter.Emit(Block(Difference,
            new AssignmentStatement("x", Variable("d"), true),
            new AssignmentStatement("y", Negate(Variable("d")), true),
            new AssignmentStatement("z", Product(Variable("d"), Variable("a"), Variable("b"), Call("sin", Variable("c"))), true)));
        Assert.Equal(
            "double tmp0 = v.b - v.a;\n" +
            "v.z = tmp0 * v.a * v.b * Math.Sin(v.c);\n" +
            "v.x = tmp0;\n" +
            "v.y = -tmp0;\n", code);
    }

    [Fact]
    public void Code_without_calls_reads_the_inputs_into_locals_even_where_that_takes_more_locals()
    {
        var code = CSharpEmitter.Emit(Block(Difference,
            new AssignmentStatement("x", Variable("d"), true),
            new AssignmentStatement("y", Negate(Variable("d")), true),
            new AssignmentStatement("z", Product(Variable("d"), Variable("a"), Variable("b"), Variable("c")), true)));
        Assert.Equal(
            "double tmp1 = v.a;\n" +
            "double tmp2 = v.b;\n" +
            "double tmp0 = tmp2 - tmp1;\n" +
            "double tmp3 = v.c;\n" +
            "v.x = tmp0;\n" +
            "v.y = -tmp0;\n" +
            "v.z = tmp0 * tmp1 * tmp2 * tmp3;\n", code);
    }

    [Fact]
    public void Inputs_read_after_an_output_are_read_into_locals_first_where_that_takes_no_more_locals_and_outputs_are_written_in_place()
    {
        var code = CSharpEmitter.Emit(Block(Difference,
            new AssignmentStatement("x", Variable("d"), true),
            new AssignmentStatement("y", Product(Variable("d"), Variable("a")), true),
            new AssignmentStatement("z", Product(Variable("d"), Variable("b")), true)));
        Assert.Equal(
            "double tmp1 = v.a;\n" +
            "double tmp2 = v.b;\n" +
            "double tmp0 = tmp2 - tmp1;\n" +
            "v.x = tmp0;\n" +
            "v.y = tmp0 * tmp1;\n" +
            "v.z = tmp0 * tmp2;\n", code);
    }

    [Fact]
    public void An_output_waits_until_the_inputs_it_may_overwrite_have_been_read_and_only_inputs_read_after_it_are_copied()
    {
        // the line through two points: its direction first, then the moments, which read p again
        var inputs = new Dictionary<string, string> { ["px"] = "v.px", ["py"] = "v.py", ["qx"] = "v.qx", ["qy"] = "v.qy" };
        var targets = new Dictionary<string, string> { ["dx"] = "v.dx", ["dy"] = "v.dy", ["m"] = "v.m" };
        var block = new CodeBlock([
            new AssignmentStatement("ex", ExprFactory.Difference(Variable("qx"), Variable("px")), false),
            new AssignmentStatement("dx", Variable("ex"), true),
            new AssignmentStatement("ey", ExprFactory.Difference(Variable("qy"), Variable("py")), false),
            new AssignmentStatement("dy", Variable("ey"), true),
            new AssignmentStatement("m", ExprFactory.Difference(Product(Variable("ey"), Variable("px")), Product(Variable("ex"), Variable("py"))), true),
        ], inputs, targets);
        Assert.Equal(
            "double tmp2 = v.px;\n" +
            "double tmp0 = v.qx - tmp2;\n" +
            "double tmp3 = v.py;\n" +
            "double tmp1 = v.qy - tmp3;\n" +
            "v.dx = tmp0;\n" +
            "v.dy = tmp1;\n" +
            "v.m = tmp1 * tmp2 - tmp0 * tmp3;\n", CSharpEmitter.Emit(block));
    }
}
