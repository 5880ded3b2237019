using GMac.Core.CodeGeneration;
using GMac.Dsl.Generation;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Generation;

/// <summary>
/// Frames of many basis vectors: operations on vectors generate without tabulating the 4^n blade
/// products, and an operation whose size is truly exponential is refused with a positioned error.
/// </summary>
public sealed class MacroCodeGenerator_LargeFrames
{
    // Only a guard against a hang: generation takes well under a second on these inputs.
    private static readonly TimeSpan SafetyTimeout = TimeSpan.FromMinutes(2);

    private static string Frame(int n)
    {
        var names = string.Join(", ", Enumerable.Range(1, n).Select(i => $"a{i}"));
        return $$"""
            define frame f as basis: {{{names}}} Euclidean end frame
            define subspace f.scalars as basis {1} end subspace
            define subspace f.vectors as basis {{{names}}} end subspace
            define multivector class f.Scalar as scalars end multivector class
            define multivector class f.Vector as vectors end multivector class
            define macro WedgeAndNorm as
                inputs: { u : f.Vector; v : f.Vector }
                outputs: { w : f.Multivector; n : f.Scalar }
                performs:
                    w = u op v;
                    n = norm(u);
            end macro
            define macro Everything as
                inputs: { u : f.Multivector; v : f.Multivector }
                outputs: { w : f.Multivector }
                performs:
                    w = u gp v;
            end macro
            """;
    }

    private static GenerationOutcome GenerateWithin(MacroCodeGenerator generator, string macro, IReadOnlyList<BindingSpec> bindings)
    {
        var task = Task.Run(() => generator.Generate(macro, bindings));
        Assert.True(task.Wait(SafetyTimeout), $"generating {macro} did not finish");
        return task.Result;
    }

    [Fact]
    public void Outer_product_and_norm_of_vectors_in_twelve_dimensions_generate_and_agree_with_the_numeric_engine()
    {
        var generator = new MacroCodeGenerator(SingleFileProject.Bind(Frame(12)));
        var bindings = new List<BindingSpec>();
        for (var i = 1; i <= 12; i++)
        {
            bindings.Add(new CoefficientBindingSpec("u", $"a{i}", BindingValues.Bare($"u{i}"), 1, 1));
            bindings.Add(new CoefficientBindingSpec("v", $"a{i}", BindingValues.Bare($"v{i}"), 1, 1));
        }
        bindings.Add(new CoefficientBindingSpec("w", "a3^a11", BindingValues.Hole("w311"), 1, 1));
        bindings.Add(new CoefficientBindingSpec("w", "a1^a2^a3", BindingValues.Hole("w123"), 1, 1));
        bindings.Add(new CoefficientBindingSpec("n", "1", BindingValues.Hole("n"), 1, 1));

        var outcome = GenerateWithin(generator, "WedgeAndNorm", bindings);

        Assert.True(outcome.Succeeded, string.Join("; ", outcome.Errors));
        var random = new Random(3);
        var atoms = outcome.Plan!.InputTexts.Keys.ToDictionary(k => k, _ => random.NextDouble() * 2 - 1);
        var values = new Dictionary<string, double>(atoms);
        foreach (var s in outcome.Result!.Block.Statements.OfType<AssignmentStatement>())
            values[s.Target] = ExprEvaluator.Evaluate(s.Value, values);
        var reference = outcome.Plan.NumericReference(atoms);
        Assert.Equal(3, reference.Count);
        foreach (var (key, expected) in reference) Assert.Equal(expected, values[key], 12);
        // Independent of both engines: (u ∧ v) on a3^a11 is u3 v11 − u11 v3; the trivector part of a 2-blade is 0.
        double Atom(string text) => atoms[outcome.Plan.InputTexts.Single(kv => kv.Value == text).Key];
        Assert.Equal(Atom("u3") * Atom("v11") - Atom("u11") * Atom("v3"), values["w.a3^a11"], 12);
        Assert.Equal(0.0, values["w.a1^a2^a3"]);
        Assert.Equal(Math.Sqrt(Enumerable.Range(1, 12).Sum(i => Atom($"u{i}") * Atom($"u{i}"))), values["n.1"], 12);
    }

    [Fact]
    public void Geometric_product_of_two_general_multivectors_in_twelve_dimensions_is_refused_at_the_statement()
    {
        var generator = new MacroCodeGenerator(SingleFileProject.Bind(Frame(12)));

        var outcome = GenerateWithin(generator, "Everything", generator.DefaultBindings("Everything"));

        var error = Assert.Single(outcome.Errors);
        Assert.Equal("GMAC0314", error.Code);
        Assert.Contains("4096 terms", error.Message);
        Assert.Contains("12-dimensional", error.Message);
        var at = Assert.IsType<Dsl.Diagnostics.SourceSpan>(error.Cause);
        Assert.Equal(("test.gmac", 17, 9), (at.FilePath, at.Line, at.Column));
    }
}
