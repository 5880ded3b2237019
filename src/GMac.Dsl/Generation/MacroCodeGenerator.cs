using System.Collections.Concurrent;
using GMac.Core.Algebra;
using GMac.Core.CodeGeneration;
using GMac.Core.Numerics;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Generation;

/// <summary>
/// Generates the statements of one binding point: reads its bindings against the macro's
/// parameters, evaluates the macro symbolically (naming intermediate results unless joined),
/// simplifies under the bindings' assumptions and the classes' normalization, and optimizes.
/// </summary>
public sealed partial class MacroCodeGenerator
{
    private const string AtomPrefix = "bp_in";

    private readonly DslProject _project;
    private readonly CoreFrames _frames = new();
    private readonly MacroCompiler _compiler;
    private readonly MacroEvaluator<double> _numeric;
    private readonly ICasAdapter _cas;

    public MacroCodeGenerator(DslProject project, ICasAdapter? cas = null)
    {
        _project = project;
        _compiler = new MacroCompiler(_frames);
        _numeric = new MacroEvaluator<double>(_frames, DoubleDomain.Instance);
        _cas = cas ?? new RuleBasedCas();
    }

    /// <param name="regionLine">The line of the binding point's <c>#region</c>, where problems of the whole point are reported.</param>
    /// <param name="filePath">The file holding the binding point: errors are reported there, at the lines of the bindings.</param>
    public GenerationOutcome Generate(string macroName, IReadOnlyList<BindingSpec> bindings, int regionLine = 1, string filePath = "")
    {
        var outcome = Outcome(macroName, bindings, regionLine);
        if (outcome.Errors.Count == 0) return outcome;
        return outcome with { Errors = outcome.Errors.Select(e => e with { Span = e.Span with { FilePath = filePath } }).ToList() };
    }

    /// <summary>A problem at a line and column of the binding point's file, which the public entry point fills in.</summary>
    private static Diagnostic Problem(DiagnosticDescriptor descriptor, string message, int line, int column) =>
        new(descriptor, SourceSpan.At("", line, column), message);

    private GenerationOutcome Outcome(string macroName, IReadOnlyList<BindingSpec> bindings, int regionLine)
    {
        var errors = new List<Diagnostic>();
        var plan = Plan(macroName, bindings, regionLine, errors);
        if (plan is null || errors.Count > 0) return new GenerationOutcome(null, errors, null);
        try
        {
            return new GenerationOutcome(CodeGenerator.Generate(plan.Request), errors, plan);
        }
        catch (MacroEvaluationException e)
        {
            var at = _project.SourceText(e.Span) is { } text ? $"in '{text}': " : "";
            errors.Add(Problem(e.Descriptor ?? DiagnosticCodes.CannotGenerate, $"macro '{macroName}' cannot be generated for these bindings: {at}{e.Message}", regionLine, 1) with { Cause = e.Span });
            return new GenerationOutcome(null, errors, null);
        }
        catch (DivideByZeroException)
        {
            // A divisor that only vanishes once simplified under the bindings' assumptions.
            errors.Add(Problem(DiagnosticCodes.GeneratedDivisionByZero,
                $"macro '{macroName}' divides by an expression that simplifies to zero for these bindings", regionLine, 1) with { Cause = plan.Macro.Declaration });
            return new GenerationOutcome(null, errors, null);
        }
        catch (AlgebraException e) when (e.ExceedsLimit)
        {
            errors.Add(Problem(DiagnosticCodes.TooLarge, $"macro '{macroName}' cannot be generated: {e.Message}", regionLine, 1) with { Cause = plan.Macro.Declaration });
            return new GenerationOutcome(null, errors, null);
        }
        catch (Exception e) when (e is AlgebraException or InvalidOperationException)
        {
            errors.Add(Problem(DiagnosticCodes.CannotGenerate, $"macro '{macroName}' cannot be generated for these bindings: {e.Message}", regionLine, 1));
            return new GenerationOutcome(null, errors, null);
        }
    }

    private BindingPointPlan? Plan(string macroName, IReadOnlyList<BindingSpec> bindings, int regionLine, List<Diagnostic> errors)
    {
        var model = _project.Model;
        if (!model.Macros.TryGetValue(macroName, out var macro))
        {
            var hint = NameSuggester.Suggest(macroName, model.Macros.Keys) is { } s ? $"; did you mean '{s}'?" : "";
            errors.Add(Problem(DiagnosticCodes.UnknownMacro, $"unknown macro '{macroName}'{hint}", regionLine, 1));
            return null;
        }

        var atoms = new AtomTable();
        var inputValues = new Dictionary<(VariableSymbol, int), Scalar>();
        var outputs = new Dictionary<string, (VariableSymbol Parameter, int Blade, int Sign)>(StringComparer.Ordinal);
        var outputTargets = new Dictionary<string, string>(StringComparer.Ordinal);
        var assumptions = Assumptions.None;

        foreach (var binding in bindings)
        {
            switch (binding)
            {
                case CoefficientBindingSpec c:
                    BindCoefficient(macro, c, atoms, inputValues, outputs, outputTargets, errors);
                    break;
                case ClassBindingSpec c:
                    assumptions = BindClass(macro, c, atoms, inputValues, outputs, outputTargets, assumptions, errors);
                    break;
            }
        }
        foreach (var a in bindings.OfType<AssumptionSpec>())
        {
            if (atoms.Find(a.Expression) is not { } variable)
            {
                errors.Add(Problem(DiagnosticCodes.UnusedAssumption, $"'{a.Expression}' in an assumption is not read by any binding of this binding point", a.Line, a.Column));
                continue;
            }
            assumptions = WithBound(assumptions, variable, a.Expression, a.Value, a.IsMinimum, a, errors);
        }
        if (errors.Count > 0) return null;
        // Only once the lines themselves are right: a mistyped blade would otherwise also leave its coefficient unbound.
        UnboundInputs(macro, inputValues, regionLine, errors);
        if (errors.Count > 0) return null;
        // Binding only inputs is enough: every output coefficient then goes to its default name.
        var defaultOutputs = outputs.Count == 0;
        if (defaultOutputs)
            foreach (var spec in DefaultBindings(macro, inputs: false))
                BindCoefficient(macro, (CoefficientBindingSpec)spec with { Line = regionLine, Column = 1 }, atoms, inputValues, outputs, outputTargets, errors);
        if (errors.Count > 0) return null;

        // Every variable coefficient is bound (checked above); class constants come from the class.
        var inputs = MacroInputs.Build(_frames, SymbolicDomain.Instance, macro, (input, blade) => inputValues.GetValueOrDefault((input, blade), Scalar.Zero));
        var relations = MacroCompiler.NormalizationRelations(macro, inputs, SideRelations.Trigonometric);
        assumptions = assumptions.WithRelations(relations);
        var join = UsesDifferentiation(macro) ? JoinMode.Joined : UsesJoin(macro) ? JoinMode.Split : JoinMode.Automatic;

        SymbolicProgram Evaluate(TemporaryRecorder? recorder)
        {
            var statements = new List<SymbolicStatement>();
            var observer = new EvaluationObserver<Scalar>
            {
                Name = recorder is null ? null : recorder.Record,
                NameStatementsOnly = recorder?.StatementsOnly ?? false,
                OutputText = (o, values) => statements.Add(Verbatim(o, values)),
            };
            IReadOnlyDictionary<VariableSymbol, Multivector<Scalar>> results;
            try
            {
                results = _compiler.Evaluator.Evaluate(macro, inputs, observer);
            }
            catch (MacroEvaluationException e) when (e.Descriptor == DiagnosticCodes.TooLarge)
            {
                // This form alone may be too large: the generator keeps the others.
                throw new FormTooLargeException(e);
            }
            foreach (var (key, (parameter, blade, sign)) in outputs)
            {
                var value = results.TryGetValue(parameter, out var mv) ? mv[new BasisBlade(blade)] : Scalar.Zero;
                statements.Add(new SymbolicOutput(key, sign < 0 ? -value : value));
            }
            return new SymbolicProgram(statements);
        }

        var request = new CodeGenerationRequest(Evaluate, atoms.Texts, outputTargets)
        {
            Simplify = s => _cas.Simplify(s, assumptions),
            Relations = relations,
            Join = join,
            EvaluatedOnce = atoms.EvaluatedOnce,
            Points = InputPoints(macro, inputValues),
        };
        return new BindingPointPlan(macro, request, atoms.DisplayTexts(), values => NumericReference(macro, inputValues, outputs, values))
        {
            DefaultOutputs = defaultOutputs,
        };
    }

    /// <summary>
    /// The inputs with vector coefficients bound to input variables as they are: points (or vectors)
    /// whose coordinates can be subtracted from those of another input bound on the same blades.
    /// </summary>
    private List<InputPoint> InputPoints(MacroSymbol macro, Dictionary<(VariableSymbol, int), Scalar> inputValues)
    {
        var points = new List<InputPoint>();
        foreach (var input in macro.Inputs)
        {
            // blades bound to something else (a constant, ½|p|² of a conformal point) follow the variables
            var coordinates = new List<(int Blade, string Name)>();
            foreach (var id in input.Class!.VariableBlades.Where(id => System.Numerics.BitOperations.PopCount((uint)id) == 1).Order())
            {
                if (!inputValues.TryGetValue((input, id), out var value) || value.Variables.Count != 1) continue;
                var name = value.Variables.First();
                if (ReferenceEquals(value, Scalar.Variable(name)) && coordinates.TrueForAll(c => c.Name != name)) coordinates.Add((id, name));
            }
            // a constant vector coefficient (no = 1 of a normalized point, from the class or the binding) makes it a position
            var position = input.Class.ConstantCoefficients.Any(c => System.Numerics.BitOperations.PopCount((uint)c.Blade) == 1)
                || input.Class.VariableBlades.Any(id => System.Numerics.BitOperations.PopCount((uint)id) == 1
                    && inputValues.TryGetValue((input, id), out var v) && v.IsConstant && !Scalar.IsZero(v));
            if (coordinates.Count >= 2)
                points.Add(new InputPoint($"{input.Class.Frame}:{string.Join(",", coordinates.Select(c => c.Blade))}", [.. coordinates.Select(c => c.Name)], position));
        }
        return points;
    }

    /// <summary>
    /// Inputs that would silently be zero where the user meant a value (a forgotten or mistyped line):
    /// an input no line binds at all, and a coefficient left out of a grade whose other coefficients
    /// are bound (v.e1 and v.e2 without v.e3). Grades left out as a whole are zero: binding a vector to
    /// a general multivector (u.e1, u.e2, u.e3, or a Vector3D class binding) means its other grades
    /// are zero. A zero is bound by writing it, //GMac.Bind("v.e3", "0").
    /// </summary>
    private void UnboundInputs(MacroSymbol macro, Dictionary<(VariableSymbol, int), Scalar> inputValues, int regionLine, List<Diagnostic> errors)
    {
        foreach (var input in macro.Inputs)
        {
            var frame = _frames[input.Class!.Frame];
            string Key(int id) => $"'{input.Name}.{frame.BladeName(new BasisBlade(id))}'";
            var blades = input.Class.VariableBlades.Order().ToList();
            var bound = blades.Where(id => inputValues.ContainsKey((input, id))).ToList();
            if (blades.Count == 0) continue;
            if (bound.Count == 0)
            {
                errors.Add(Problem(DiagnosticCodes.UnboundInput,
                    $"input '{input.Name}' of macro '{macro.Name}' is bound by no line; bind it (e.g. //GMac.Bind(\"{input.Name}\", \"<class binding>\", obj)), " +
                    $"or write its coefficients {string.Join(", ", blades.Select(Key))} as \"0\" to mean zero", regionLine, 1));
                continue;
            }
            var grades = bound.Select(id => System.Numerics.BitOperations.PopCount((uint)id)).ToHashSet();
            var missing = blades.Where(id => !bound.Contains(id) && grades.Contains(System.Numerics.BitOperations.PopCount((uint)id))).ToList();
            if (missing.Count == 0) continue;
            errors.Add(Problem(DiagnosticCodes.UnboundInput,
                $"input coefficient{(missing.Count > 1 ? "s" : "")} {string.Join(", ", missing.Select(Key))} of macro '{macro.Name}' {(missing.Count > 1 ? "are" : "is")} bound by no line, " +
                $"though other coefficients of {(missing.Count > 1 ? "their" : "its")} grade are; bind {(missing.Count > 1 ? "them" : "it")}, or write \"0\" to mean zero", regionLine, 1));
        }
    }

    /// <summary>
    /// Adds a minimum or maximum for a bound expression; one that leaves no value between the
    /// minimum and the maximum is reported at the binding line that caused it, and not added.
    /// </summary>
    private static Assumptions WithBound(Assumptions assumptions, string variable, string expression, Rational value, bool isMinimum,
        BindingSpec at, List<Diagnostic> errors)
    {
        var min = assumptions.MinimumOf(variable);
        var max = assumptions.MaximumOf(variable);
        if (isMinimum ? max is { } hi && value > hi : min is { } lo && value < lo)
        {
            var (lower, upper) = isMinimum ? (value, max!.Value) : (min!.Value, value);
            errors.Add(Problem(DiagnosticCodes.EmptyAssumption,
                $"'{expression}' is assumed to be at least {lower} and at most {upper}: no value satisfies both", at.Line, at.Column));
            return assumptions;
        }
        return isMinimum ? assumptions.WithMinimum(variable, value) : assumptions.WithMaximum(variable, value);
    }

    /// <summary>The block's parts with the values of its references, in order.</summary>
    private static SymbolicVerbatim Verbatim(BoundOutputStatement output, IReadOnlyList<Scalar> values)
    {
        // Text, value, text, …, text: a reference always stands between two texts (empty ones included).
        var parts = new List<(string?, Scalar?)>();
        var i = 0;
        var text = "";
        foreach (var part in output.Parts)
        {
            if (part is not OutputReferencePart)
            {
                text = part.Text;
                continue;
            }
            parts.Add((text, null));
            parts.Add((null, i < values.Count ? values[i] : Scalar.Zero));
            text = "";
            i++;
        }
        parts.Add((text, null));
        return new SymbolicVerbatim(parts);
    }

    /// <summary>The macro run on doubles: the independent reference that <c>gmac verify</c> checks generated code against.</summary>
    private IReadOnlyDictionary<string, double> NumericReference(MacroSymbol macro, Dictionary<(VariableSymbol, int), Scalar> inputValues,
        Dictionary<string, (VariableSymbol Parameter, int Blade, int Sign)> outputs, IReadOnlyDictionary<string, double> atomValues)
    {
        var inputs = MacroInputs.Build(_frames, DoubleDomain.Instance, macro, (input, blade) =>
            inputValues.TryGetValue((input, blade), out var v) ? v.Evaluate(atomValues) : 0.0);
        var results = _numeric.Evaluate(macro, inputs);
        return outputs.ToDictionary(o => o.Key, o =>
        {
            var value = results.TryGetValue(o.Value.Parameter, out var mv) ? mv[new BasisBlade(o.Value.Blade)] : 0.0;
            return o.Value.Sign < 0 ? -value : value;
        }, StringComparer.Ordinal);
    }

    /// <summary>
    /// Whether the macro or a macro it calls (at any depth) differentiates. Remembered per macro, so
    /// each macro's statements are searched once per generator, not once per caller that reaches it.
    /// </summary>
    private bool UsesDifferentiation(MacroSymbol macro, HashSet<MacroSymbol>? visiting = null)
    {
        if (_differentiates.TryGetValue(macro, out var known)) return known;
        visiting ??= [];
        if (!visiting.Add(macro)) return false; // a call cycle, already reported by the binder
        var result = macro.Statements.Any(s => BoundTree.Contains<BoundDifferentiation>(s)) || macro.Callees.Any(c => UsesDifferentiation(c, visiting));
        _differentiates[macro] = result;
        return result;
    }

    private readonly ConcurrentDictionary<MacroSymbol, bool> _differentiates = new();

    private static bool UsesJoin(MacroSymbol macro) => macro.Statements.Any(s => s is BoundJoinStatement);

}
