using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Compilation;

/// <summary>
/// Every library macro compiled symbolically, then evaluated at random inputs,
/// equals the same statements run directly on doubles.
/// </summary>
public sealed class MacroCompiler_AgreesWithNumeric
{
    private static readonly Lazy<DslProject> Library = new(() => DslProject.Load(RepositoryPaths.DslLibrary));

    public static TheoryData<string> MacroNames()
    {
        var data = new TheoryData<string>();
        foreach (var name in Library.Value.Model.Macros.Keys.Order(StringComparer.Ordinal)) data.Add(name);
        return data;
    }

    [Theory]
    [MemberData(nameof(MacroNames))]
    public void Symbolic_outputs_evaluate_to_the_numeric_outputs(string macroName)
    {
        var macro = Library.Value.Model.Macros[macroName];
        var frames = new CoreFrames();
        var compiler = new MacroCompiler(frames);
        var symbolicInputs = SymbolicMacro.Inputs(frames, macro);
        var (symbolic, temporaries) = Compile(compiler, macro, symbolicInputs);
        var usesDiff = macro.Statements.OfType<BoundAssignment>().Any(a => ContainsDiff(a.Value))
            || macro.Callees.Any(c => c.Statements.OfType<BoundAssignment>().Any(a => ContainsDiff(a.Value)));

        var random = new Random(macroName.Aggregate(7, (h, c) => h * 31 + c));
        for (var trial = 0; trial < 3; trial++)
        {
            // Positive values keep log, sqrt and inverses of the library's formulas defined.
            var values = symbolicInputs.Values.SelectMany(m => m.Terms.SelectMany(t => t.Coefficient.Variables))
                .Distinct().ToDictionary(v => v, _ => 0.3 + 1.4 * random.NextDouble());
            var numericInputs = symbolicInputs.ToDictionary(kv => kv.Key, kv => kv.Value.Evaluate(values));
            foreach (var (name, value) in temporaries) values[name] = value.Evaluate(values);
            var numeric = new MacroEvaluator<double>(frames, DoubleDomain.Instance).Evaluate(macro, numericInputs);

            Assert.Equal(numeric.Keys.Select(k => k.Name).Order(), symbolic.Keys.Select(k => k.Name).Order());
            foreach (var (output, expected) in numeric)
            {
                var actual = symbolic[output].Evaluate(values);
                // Central differences carry ~h² truncation error; exact paths agree to rounding.
                var tolerance = usesDiff ? 1e-5 : 1e-9;
                for (var id = 0; id < expected.Frame.BladeCount; id++)
                {
                    var blade = new BasisBlade(id);
                    var (e, a) = (expected[blade], actual[blade]);
                    // Random inputs can leave a macro's domain (two trivectors that are no lines have no motor):
                    // both evaluations are then NaN, which is agreement.
                    if (double.IsNaN(e) && double.IsNaN(a)) continue;
                    Assert.True(Math.Abs(e - a) <= tolerance * (1 + Math.Abs(e)),
                        $"{macroName}.{output.Name} on {expected.Frame.BladeName(blade)}: numeric {e}, symbolic {a}");
                }
            }
        }
    }

    /// <summary>
    /// The macro's outputs as expressions of its inputs; where that is too large to expand (the exp
    /// of a log of a product), as expressions of named intermediate values, as generated code has
    /// them, with those values in order of definition.
    /// </summary>
    private static (IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>>, List<(string, Scalar)>) Compile(
        MacroCompiler compiler, MacroSymbol macro, IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> inputs)
    {
        var temporaries = new List<(string, Scalar)>();
        try
        {
            return (compiler.Evaluator.Evaluate(macro, inputs), temporaries);
        }
        catch (MacroEvaluationException e) when (e.Descriptor == Dsl.Diagnostics.DiagnosticCodes.TooLarge)
        {
            Multivector<Scalar> Name(Multivector<Scalar> m) => Multivector<Scalar>.FromTerms(m.Frame, m.Terms.Select(t =>
            {
                if (t.Coefficient.IsConstant) return (t.Blade, t.Coefficient);
                var name = $"tmp{temporaries.Count}";
                temporaries.Add((name, t.Coefficient));
                return (t.Blade, Scalar.Variable(name));
            }));
            return (compiler.Evaluator.Evaluate(macro, inputs, new EvaluationObserver<Scalar> { Name = Name }), temporaries);
        }
    }

    [Fact]
    public void Normal_to_vectors_is_the_cross_product()
    {
        var macro = Library.Value.Model.Macros["NormalToVectors"];
        var w = SymbolicMacro.Compile(macro).Values.Single();
        // Thesis §4.10.1: wx = u.y v.z − u.z v.y, wy = u.z v.x − u.x v.z, wz = u.x v.y − u.y v.x.
        var values = new Dictionary<string, double> { ["u.e1"] = 1, ["u.e2"] = 2, ["u.e3"] = 3, ["v.e1"] = -4, ["v.e2"] = 5, ["v.e3"] = 0.5 };
        var n = w.Evaluate(values);
        Assert.Equal(2 * 0.5 - 3 * 5, n["e1"], 12);
        Assert.Equal(3 * -4 - 1 * 0.5, n["e2"], 12);
        Assert.Equal(1 * 5 - 2 * -4, n["e3"], 12);
    }

    [Fact]
    public void Parametric_normal_matches_equation_4_11()
    {
        var macro = Library.Value.Model.Macros["NormalToParametricVectors"];
        var w = SymbolicMacro.Compile(macro).Values.Single();
        foreach (var x in new[] { -1.3, 0.2, 2.9 })
        {
            var n = w.Evaluate(new Dictionary<string, double> { ["x.scalar"] = x });
            var (u1, u2) = (Math.Sin(x), Math.Cos(x));
            // (4.11): w1 = u2 − u1, w4 = u1² − u2². Its w2 = −w1 is a typo: (4.9) gives
            // w2 = b d = −(u1 v4 − u4 v1) = u2 − u1 = w1 (the cross product agrees).
            Assert.Equal(u2 - u1, n["e1"], 12);
            Assert.Equal(u2 - u1, n["e2"], 12);
            Assert.Equal(u1 * u1 - u2 * u2, n["e3"], 12);
        }
    }

    [Fact]
    public void Normalized_rotor_gives_the_reduced_diagonal_of_equation_7_6()
    {
        var macro = Library.Value.Model.Macros["RotorToMatrix"];
        var frames = new CoreFrames();
        var inputs = SymbolicMacro.Inputs(frames, macro);
        var outputs = new MacroCompiler(frames).Evaluator.Evaluate(macro, inputs);
        var relations = MacroCompiler.NormalizationRelations(macro, inputs, SideRelations.None);
        var c1 = outputs.Single(o => o.Key.Name == "c1").Value;
        // R = w + x e2^e3 + y e3^e1 + z e1^e2 (7.7): y is minus the e1^e3 coefficient.
        var y = Scalar.Variable("r.e1_e3");
        var z = Scalar.Variable("r.e1_e2");
        var expected = Scalar.One - Scalar.Constant(2) * (y * y + z * z);
        Assert.Equal(expected.ToString(), relations.Reduce(c1["e1"]).ToString());
    }

    [Fact]
    public void Circle_curve_matches_equation_6_5()
    {
        var macro = Library.Value.Model.Macros["CircleCurvePoint"];
        var u = SymbolicMacro.Compile(macro).Values.Single();
        var (c1, c2, c3, r, t) = (0.5, -1.0, 2.0, 1.5, 0.3);
        var n = u.Evaluate(new Dictionary<string, double>
        {
            ["c.e1"] = c1, ["c.e2"] = c2, ["c.e3"] = c3, ["r.scalar"] = r, ["t.scalar"] = t,
        });
        Assert.Equal(c1 + r * Math.Cos(2 * Math.PI * t), n["e1"], 9);
        Assert.Equal(c2 + r * Math.Sin(2 * Math.PI * t), n["e2"], 9);
        Assert.Equal(c3, n["e3"], 9);
    }

    [Fact]
    public void Skew_line_parameters_give_the_closest_points()
    {
        var macro = Library.Value.Model.Macros["SkewLinesClosestPoints"];
        var outputs = SymbolicMacro.Compile(macro);
        double[] p1 = [0.2, -1, 0.5], d1 = [1, 0.3, -0.2], p2 = [1, 2, -1], d2 = [-0.4, 1, 0.7];
        var values = new Dictionary<string, double>();
        for (var i = 0; i < 3; i++)
        {
            values[$"p1.e{i + 1}"] = p1[i]; values[$"d1.e{i + 1}"] = d1[i];
            values[$"p2.e{i + 1}"] = p2[i]; values[$"d2.e{i + 1}"] = d2[i];
        }
        var t1 = outputs.Single(o => o.Key.Name == "t1").Value.Evaluate(values).ScalarPart;
        var t2 = outputs.Single(o => o.Key.Name == "t2").Value.Evaluate(values).ScalarPart;
        // The segment between the closest points is orthogonal to both directions.
        var gap = Enumerable.Range(0, 3).Select(i => p2[i] + t2 * d2[i] - p1[i] - t1 * d1[i]).ToArray();
        Assert.Equal(0, gap.Zip(d1).Sum(x => x.First * x.Second), 9);
        Assert.Equal(0, gap.Zip(d2).Sum(x => x.First * x.Second), 9);
    }

    private static bool ContainsDiff(BoundExpression e) => e switch
    {
        BoundDifferentiation => true,
        BoundUnaryOperation u => ContainsDiff(u.Operand),
        BoundBinaryOperation b => ContainsDiff(b.Left) || ContainsDiff(b.Right),
        BoundCast c => ContainsDiff(c.Operand),
        BoundGradeProjection g => ContainsDiff(g.Operand),
        BoundMacroCall m => m.Arguments.Any(ContainsDiff) || m.Macro.Statements.OfType<BoundAssignment>().Any(a => ContainsDiff(a.Value)),
        _ => false,
    };
}
