using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// exp(a op b) of two vectors in 4D generates with and without <c>join on</c>: a wedge of vectors is
/// a blade by structure, so its square is taken as a scalar however the macro names temporaries.
/// </summary>
public sealed class MacroCodeGenerator_ExpOfOuterProducts
{
    private const string Source = """
        define frame e4 as
            basis: {e1, e2, e3, e4}
            Euclidean
        end frame
        define subspace e4.vectors as basis {e1, e2, e3, e4} end subspace
        define multivector class e4.Vector as vectors end multivector class
        define macro Direct as
            inputs: { a : e4.Vector; b : e4.Vector; x : e4.Vector }
            outputs: { y : e4.Vector }
            performs:
                y = apply(exp(a op b), x);
        end macro
        define macro Named as
            inputs: { a : e4.Vector; b : e4.Vector; x : e4.Vector }
            outputs: { y : e4.Vector }
            performs:
                plane = -0.5 * (a op b);
                y = apply(exp(plane), x);
        end macro
        define macro Joined as
            inputs: { a : e4.Vector; b : e4.Vector; x : e4.Vector }
            outputs: { y : e4.Vector }
            performs:
                join on;
                y = apply(exp(a op b), x);
        end macro
        """;

    private static Dictionary<string, double> Run(string macro, Dictionary<string, double> inputs)
    {
        var generator = new MacroCodeGenerator(DslProject.FromSources([("test.gmac", Source)]));
        var outcome = generator.Generate(macro, generator.DefaultBindings(macro));
        Assert.True(outcome.Succeeded, $"{macro}: {string.Join("; ", outcome.Errors)}");
        var block = outcome.Result!.Block;
        var values = new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var (variable, text) in block.InputText) values[variable] = inputs[text];
        foreach (var s in block.Statements.OfType<AssignmentStatement>()) values[s.Target] = ExprEvaluator.Evaluate(s.Value, values);
        return block.OutputTargets.ToDictionary(o => o.Value, o => values[o.Key], StringComparer.Ordinal);
    }

    [Fact]
    public void Exp_of_a_wedge_of_vectors_generates_whether_or_not_temporaries_are_joined()
    {
        var inputs = new Dictionary<string, double>(StringComparer.Ordinal)
        {
            ["a_e1"] = 0.3, ["a_e2"] = -0.7, ["a_e3"] = 0.2, ["a_e4"] = 0.9,
            ["b_e1"] = 1.1, ["b_e2"] = 0.4, ["b_e3"] = -0.6, ["b_e4"] = 0.1,
            ["x_e1"] = 1.5, ["x_e2"] = -2.0, ["x_e3"] = 0.25, ["x_e4"] = 0.75,
        };
        var joined = Run("Joined", inputs);
        var direct = Run("Direct", inputs);
        foreach (var (name, value) in joined) Assert.Equal(value, direct[name], 12);
        // A rotation keeps the length of x.
        var length = Math.Sqrt(Run("Named", inputs).Values.Sum(v => v * v));
        Assert.Equal(Math.Sqrt(1.5 * 1.5 + 4 + 0.0625 + 0.5625), length, 12);
    }
}
