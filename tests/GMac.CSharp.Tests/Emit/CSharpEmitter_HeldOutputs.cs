using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

/// <summary>
/// Outputs whose targets may be inputs read after them are written at the end. One whose value is
/// already held by a temporary (a difference that is both an output and an operand) is written
/// from that temporary: a second local holding a copy is code the hand writer would not write.
/// </summary>
public class CSharpEmitter_HeldOutputs
{
    private static CodeBlock Block()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "v.a", ["b"] = "v.b" };
        CodeStatement[] statements =
        [
            new AssignmentStatement("d", Difference(Variable("b"), Variable("a")), false),
            new AssignmentStatement("o1", Variable("d"), true),
            new AssignmentStatement("o2", Negate(Variable("d")), true),
            new AssignmentStatement("o3", Product(Variable("d"), Variable("a")), true),
            new AssignmentStatement("o4", Product(Variable("d"), Variable("b")), true),
        ];
        var targets = new Dictionary<string, string> { ["o1"] = "v.x", ["o2"] = "v.y", ["o3"] = "v.z", ["o4"] = "v.w" };
        return new CodeBlock(statements, inputs, targets);
    }

    [Fact]
    public void An_output_that_is_a_temporary_or_its_negation_is_written_from_the_temporary_after_the_last_read()
    {
        var code = CSharpEmitter.Emit(Block());
        Assert.Equal(
            "double tmp0 = v.b - v.a;\n" +
            "double tmp1 = tmp0 * v.a;\n" +
            "v.w = tmp0 * v.b;\n" +
            "v.x = tmp0;\n" +
            "v.y = -tmp0;\n" +
            "v.z = tmp1;\n", code);
    }
}
