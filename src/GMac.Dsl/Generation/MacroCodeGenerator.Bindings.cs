using GMac.Core.Algebra;
using GMac.Core.Symbolic;
using GMac.Dsl.Compilation;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Generation;

public sealed partial class MacroCodeGenerator
{
    private VariableSymbol? FindParameter(MacroSymbol macro, string name, BindingSpec at, List<Diagnostic> errors)
    {
        var parameter = macro.Inputs.Concat(macro.Outputs).FirstOrDefault(p => p.Name == name);
        if (parameter is not null) return parameter;
        var hint = NameSuggester.Suggest(name, macro.Inputs.Concat(macro.Outputs).Select(p => p.Name)) is { } s ? $"; did you mean '{s}'?" : "";
        errors.Add(Problem(DiagnosticCodes.UnknownParameter, $"macro '{macro.Name}' has no input or output named '{name}'{hint}", at.Line, at.Column));
        return null;
    }

    private void BindCoefficient(MacroSymbol macro, CoefficientBindingSpec c, AtomTable atoms,
        Dictionary<(VariableSymbol, int), Scalar> inputValues,
        Dictionary<string, (VariableSymbol, int, int)> outputs, Dictionary<string, string> outputTargets, List<Diagnostic> errors)
    {
        if (FindParameter(macro, c.Parameter, c, errors) is not { } parameter) return;
        var frame = _frames[parameter.Class!.Frame];
        if (!frame.TryParseBlade(c.Blade, out var blade, out var sign))
        {
            errors.Add(Problem(DiagnosticCodes.UnknownBlade, $"'{c.Blade}' is not a blade of frame '{frame.Name}' (basis vectors: {string.Join(", ", frame.BasisVectorNames)})", c.Line, c.Column));
            return;
        }
        var key = $"{parameter.Name}.{frame.BladeName(blade)}";
        if (parameter.Kind == VariableKind.Input)
        {
            if (!parameter.Class.VariableBlades.Contains(blade.Id))
            {
                errors.Add(Problem(DiagnosticCodes.NotACoefficient, $"'{key}' is not a variable coefficient of class '{parameter.Class.QualifiedName}' of input '{parameter.Name}'", c.Line, c.Column));
                return;
            }
            if (ParseValue(c, atoms, errors) is not { } value) return;
            if (!inputValues.TryAdd((parameter, blade.Id), sign < 0 ? -value : value))
                errors.Add(Problem(DiagnosticCodes.BoundTwice, $"'{key}' is bound twice", c.Line, c.Column));
            return;
        }

        if (!parameter.Class.AllBlades.Contains(blade.Id))
        {
            errors.Add(Problem(DiagnosticCodes.NotACoefficient, $"'{key}' is not a coefficient of class '{parameter.Class.QualifiedName}' of output '{parameter.Name}'", c.Line, c.Column));
            return;
        }
        var target = c.Value.Target;
        if (string.IsNullOrWhiteSpace(target))
        {
            errors.Add(Problem(DiagnosticCodes.OutputNotATarget, $"output '{key}' must be bound to an assignable target such as \"<wx>\", not \"{c.Value.Text}\"", c.Line, c.Column));
            return;
        }
        if (!outputs.TryAdd(key, (parameter, blade.Id, sign)))
        {
            errors.Add(Problem(DiagnosticCodes.BoundTwice, $"'{key}' is bound twice", c.Line, c.Column));
            return;
        }
        outputTargets[key] = target;
    }

    /// <summary>An input value: a number, a bare target-language expression, or a scalar expression over its holes.</summary>
    private static Scalar? ParseValue(CoefficientBindingSpec c, AtomTable atoms, List<Diagnostic> errors)
    {
        switch (c.Value)
        {
            case NumberValue n:
                return Scalar.Constant(n.Value);
            case HostExpression h:
                return Atom(h with { Text = h.Text.Trim() }, atoms);
            case TemplateValue { Problem: { } problem } t:
                errors.Add(Problem(DiagnosticCodes.InvalidBindingValue, $"{problem} in \"{t.Text}\"", c.Line, c.Column));
                return null;
        }
        var template = (TemplateValue)c.Value;
        var expression = new System.Text.StringBuilder();
        foreach (var part in template.Parts)
            expression.Append(part is TemplateHole hole ? Atom(hole.Expression, atoms).ToString() : ((ScalarTextPart)part).Text);
        try
        {
            var value = Scalar.Parse(expression.ToString());
            var stray = value.Variables.FirstOrDefault(v => !v.StartsWith(AtomPrefix, StringComparison.Ordinal));
            if (stray is null) return value;
            errors.Add(Problem(DiagnosticCodes.InvalidBindingValue, $"\"{c.Value.Text}\" names '{stray}', which is neither a number nor a <target-language expression>", c.Line, c.Column));
        }
        catch (ScalarSyntaxException e)
        {
            errors.Add(Problem(DiagnosticCodes.InvalidBindingValue, $"\"{c.Value.Text}\" is not a valid scalar expression: {e.Message}", c.Line, c.Column));
        }
        return null;
    }

    /// <summary>The variable for a host expression read by the code; one with effects (a call, an increment) is evaluated once.</summary>
    private static Scalar Atom(HostExpression expression, AtomTable atoms) => atoms.For(expression.HasEffects ? atoms.Once(expression.Text) : expression.Text);

    private Assumptions BindClass(MacroSymbol macro, ClassBindingSpec c, AtomTable atoms,
        Dictionary<(VariableSymbol, int), Scalar> inputValues,
        Dictionary<string, (VariableSymbol, int, int)> outputs, Dictionary<string, string> outputTargets,
        Assumptions assumptions, List<Diagnostic> errors)
    {
        if (FindParameter(macro, c.Parameter, c, errors) is not { } parameter) return assumptions;
        var model = _project.Model;
        if (!model.ClassBindings.TryGetValue(c.ClassBinding, out var binding))
        {
            var hint = NameSuggester.Suggest(c.ClassBinding, model.ClassBindings.Keys) is { } s ? $"; did you mean '{s}'?" : "";
            errors.Add(Problem(DiagnosticCodes.ClassBindingMismatch, $"unknown class binding '{c.ClassBinding}'{hint}", c.Line, c.Column));
            return assumptions;
        }
        if (binding.Frame != parameter.Class!.Frame)
        {
            errors.Add(Problem(DiagnosticCodes.ClassBindingMismatch, $"class binding '{binding.Name}' is on frame '{binding.Frame.Name}', but '{parameter.Name}' of macro '{macro.Name}' is on frame '{parameter.Class.Frame.Name}'", c.Line, c.Column));
            return assumptions;
        }
        var frame = _frames[binding.Frame];
        var target = c.Target.Trim();
        string Member(string path) => $"{target}.{path}";

        if (parameter.Kind == VariableKind.Input)
        {
            // An object with effects (Next(), a[i++]) is read once, not once per coefficient.
            if (c.TargetHasEffects) target = atoms.Once(target);
            var observer = new EvaluationObserver<Scalar> { Member = path => atoms.For(Member(path)) };
            foreach (var coefficient in binding.Coefficients)
            {
                if (!parameter.Class.VariableBlades.Contains(coefficient.Blade.Mask)) continue; // class constants stay
                var value = _compiler.Evaluator.EvaluateScalar(coefficient.Value, observer);
                if (!inputValues.TryAdd((parameter, coefficient.Blade.Mask), coefficient.Blade.Sign < 0 ? -value : value))
                    errors.Add(Problem(DiagnosticCodes.BoundTwice, $"'{parameter.Name}.{frame.BladeName(new BasisBlade(coefficient.Blade.Mask))}' is bound twice", c.Line, c.Column));
            }
            foreach (var (member, min) in binding.Minimums)
                if (atoms.Find(Member(member)) is { } v) assumptions = WithBound(assumptions, v, Member(member), min, true, c, errors);
            foreach (var (member, max) in binding.Maximums)
                if (atoms.Find(Member(member)) is { } v) assumptions = WithBound(assumptions, v, Member(member), max, false, c, errors);
            return assumptions;
        }

        foreach (var coefficient in binding.Coefficients)
        {
            var key = $"{parameter.Name}.{frame.BladeName(new BasisBlade(coefficient.Blade.Mask))}";
            if (coefficient.Value is not BoundMemberReference member)
            {
                errors.Add(Problem(DiagnosticCodes.OutputNotATarget, $"class binding '{binding.Name}' cannot receive output '{parameter.Name}': its coefficient of {frame.BladeName(new BasisBlade(coefficient.Blade.Mask))} is an expression, not a member", c.Line, c.Column));
                continue;
            }
            if (!parameter.Class.AllBlades.Contains(coefficient.Blade.Mask)) continue;
            if (!outputs.TryAdd(key, (parameter, coefficient.Blade.Mask, coefficient.Blade.Sign)))
            {
                errors.Add(Problem(DiagnosticCodes.BoundTwice, $"'{key}' is bound twice", c.Line, c.Column));
                continue;
            }
            outputTargets[key] = Member(member.Path);
        }
        return assumptions;
    }
}
