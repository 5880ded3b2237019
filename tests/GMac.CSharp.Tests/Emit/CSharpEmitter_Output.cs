using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;
using static GMac.Core.CodeGeneration.ExprFactory;

namespace GMac.CSharp.Tests.Emit;

public class CSharpEmitter_Output
{
    private static CodeBlock Block(IReadOnlyDictionary<string, string> inputs, params CodeStatement[] statements) =>
        new(statements, inputs, statements.OfType<AssignmentStatement>().Where(s => s.IsOutput).ToDictionary(s => s.Target, s => s.Target + "Target", StringComparer.Ordinal));

    [Fact]
    public void Temporaries_avoid_names_in_scope_and_are_declared_once()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "a", ["b"] = "b" };
        var block = Block(inputs,
            new AssignmentStatement("x", Sum(Variable("a"), Variable("b")), false),
            new AssignmentStatement("o", Product(Variable("x"), Variable("x")), true));
        var code = CSharpEmitter.Emit(block, new CSharpEmitOptions { IsNameTaken = n => n == "tmp0", Indent = "    " });
        Assert.Equal("    double t0 = a + b;\n    oTarget = t0 * t0;\n", code);
    }

    [Fact]
    public void Complex_input_expressions_are_parenthesized_and_math_calls_use_system_math()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "p.x + 1", ["b"] = "v[i].y", ["c"] = "angle" };
        var block = Block(inputs,
            new AssignmentStatement("o", Product(Variable("a"), Variable("b"), Call("cos", Variable("c"))), true));
        Assert.Equal("oTarget = (p.x + 1) * v[i].y * Math.Cos(angle);\n", CSharpEmitter.Emit(block));
    }

    [Fact]
    public void Header_reports_the_statistics_and_verbatim_text_keeps_its_placeholders()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "a" };
        var block = Block(inputs,
            new VerbatimStatement([VerbatimPart.Literal("if ("), VerbatimPart.Expression(Variable("a")), VerbatimPart.Literal(" != 0.0)")]),
            new AssignmentStatement("o", Quotient(ConstantExpr.One, Variable("a")), true));
        var code = CSharpEmitter.Emit(block, new CSharpEmitOptions { IncludeStatistics = true });
        Assert.Equal("// GMac: 0 additions/subtractions, 0 multiplications, 1 divisions, 0 function calls, 0 temporaries\nif (a != 0.0)\noTarget = 1.0 / a;\n", code);
    }

    [Fact]
    public void A_value_in_verbatim_text_keeps_its_precedence_among_the_operators_around_it()
    {
        var inputs = new Dictionary<string, string> { ["a"] = "a", ["b"] = "b" };
        var block = Block(inputs,
            new VerbatimStatement([VerbatimPart.Literal("r = 2 * "), VerbatimPart.Expression(Difference(Variable("a"), Variable("b"))),
                VerbatimPart.Literal(" + "), VerbatimPart.Expression(ConstantExpr.From(-1)), VerbatimPart.Literal(" * "), VerbatimPart.Expression(Variable("a")),
                VerbatimPart.Literal(" / "), VerbatimPart.Expression(ConstantExpr.From(3)), VerbatimPart.Literal(";")]));
        Assert.Equal("r = 2 * (a - b) + (-1.0) * a / 3.0;\n", CSharpEmitter.Emit(block));
    }

    [Fact]
    public void Literals_are_always_doubles()
    {
        Assert.Equal("2.0", ExprPrinter.Literal(2));
        Assert.Equal("0.5", ExprPrinter.Literal(0.5));
        Assert.Equal("1E-20", ExprPrinter.Literal(1e-20));
    }

    [Fact]
    public void Parentheses_follow_the_tree()
    {
        var (a, b, c) = (Variable("a"), Variable("b"), Variable("c"));
        Assert.Equal("a * (b - c)", Product(a, Difference(b, c)).ToString());
        Assert.Equal("a / (b * c)", Quotient(a, Product(b, c)).ToString());
        Assert.Equal("(a + b) / c", Quotient(Sum(a, b), c).ToString());
        Assert.Equal("-(a + b)", Negate(Sum(a, b)).ToString());
    }
}
