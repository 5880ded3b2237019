using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

public class CSharpEmitter_SinCos
{
    private static CodeBlock Block(IReadOnlyDictionary<string, string> inputs, params CodeStatement[] statements) =>
        new(statements, inputs, statements.OfType<AssignmentStatement>().Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target + "Target", StringComparer.Ordinal));

    private static readonly Dictionary<string, string> Inputs = new() { ["a"] = "angle", ["b"] = "b" };

    [Fact]
    public void Sine_and_cosine_of_one_argument_are_computed_together_at_the_first_of_them()
    {
        var twice = Product(Constant(2), Variable("a"));
        var block = Block(Inputs,
            new AssignmentStatement("c", Call("cos", twice), false),
            new AssignmentStatement("x", Sum(Variable("b"), Variable("b")), false),
            new AssignmentStatement("s", Call("sin", twice), false),
            new AssignmentStatement("o", Sum(Product(Variable("c"), Variable("x")), Variable("s")), true));
        var code = CSharpEmitter.Emit(block);
        Assert.Equal("var (tmp2, tmp0) = Math.SinCos(2.0 * angle);\ndouble tmp1 = b + b;\noTarget = tmp0 * tmp1 + tmp2;\n", code);
    }

    [Fact]
    public void Float_code_uses_mathf_sincos()
    {
        var block = Block(Inputs,
            new AssignmentStatement("s", Call("sin", Variable("a")), false),
            new AssignmentStatement("c", Call("cos", Variable("a")), false),
            new AssignmentStatement("o", Product(Variable("s"), Variable("c")), true));
        var code = CSharpEmitter.Emit(block, new CSharpEmitOptions { ScalarType = "float" });
        Assert.Equal("var (tmp0, tmp1) = MathF.SinCos(angle);\noTarget = tmp0 * tmp1;\n", code);
    }

    [Fact]
    public void Different_arguments_outputs_and_lone_calls_are_left_alone()
    {
        var block = Block(Inputs,
            new AssignmentStatement("s", Call("sin", Variable("a")), false),
            new AssignmentStatement("c", Call("cos", Variable("b")), false),
            new AssignmentStatement("o", Call("cos", Variable("a")), true),
            new AssignmentStatement("p", Product(Variable("s"), Variable("c")), true));
        var code = CSharpEmitter.Emit(block);
        Assert.Equal("double tmp0 = Math.Sin(angle);\ndouble tmp1 = Math.Cos(b);\noTarget = Math.Cos(angle);\npTarget = tmp0 * tmp1;\n", code);
    }
}
