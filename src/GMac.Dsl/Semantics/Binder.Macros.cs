using System.Text.RegularExpressions;
using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;
using static GMac.Dsl.Syntax.Generated.GMacDslParser;

namespace GMac.Dsl.Semantics;

internal sealed partial class Binder
{
    /// <summary>Variables of the macro being bound, and what has been assigned so far.</summary>
    private sealed class MacroContext(Binder binder, MacroSymbol macro, HashSet<string> assignedSomewhere)
    {
        public MacroSymbol Macro { get; } = macro;
        public Dictionary<string, VariableSymbol> Variables { get; } = new(StringComparer.Ordinal);
        public Dictionary<VariableSymbol, ExpressionType> Types { get; } = [];
        public HashSet<VariableSymbol> Assigned { get; } = [];
        public List<VariableSymbol> Temporaries { get; } = [];
        public HashSet<MacroSymbol> Callees { get; } = [];

        public BoundExpression? Read(string name, SourceSpan span)
        {
            if (Variables.TryGetValue(name, out var variable))
            {
                if (variable.Kind == VariableKind.Output && !Assigned.Contains(variable))
                {
                    binder._diagnostics.ReportOutputReadBeforeAssignment(span, name);
                    return null;
                }
                variable.IsReferenced = true;
                return new BoundVariableReference(variable, Types[variable], span);
            }
            if (assignedSomewhere.Contains(name))
            {
                binder._diagnostics.ReportUsedBeforeAssignment(span, name);
                return null;
            }
            binder.ReportUnknown(span, "multivector", name, Variables.Keys.Append("pi"));
            return null;
        }
    }

    private MacroSymbol? DeclareMacro(MacroDefinitionContext syntax)
    {
        var name = syntax.name().GetText();
        if (_macros.TryGetValue(name, out var existing))
        {
            _diagnostics.ReportDuplicate(Span(syntax.name()), "macro", name, existing.Declaration);
            return null;
        }
        var macro = new MacroSymbol(name, Span(syntax.name()));
        _macros[name] = macro;
        return macro;
    }

    private readonly Dictionary<MacroSymbol, MacroContext> _macroContexts = [];

    private void BindMacroSignature(MacroDefinitionContext syntax, MacroSymbol macro)
    {
        var assignedSomewhere = new HashSet<string>(StringComparer.Ordinal);
        foreach (var statement in syntax.statement())
        {
            if (statement is AssignmentStatementContext a) assignedSomewhere.Add(a.name().GetText());
            if (statement is CallStatementContext c)
                foreach (var arg in c.callArgument())
                    if (arg.expr() is NameExprContext n) assignedSomewhere.Add(n.GetText());
        }
        var context = new MacroContext(this, macro, assignedSomewhere);
        _macroContexts[macro] = context;
        var lists = syntax.parameterList();
        macro.Inputs = BindParameters(lists[0], VariableKind.Input, context);
        macro.Outputs = BindParameters(lists[1], VariableKind.Output, context);
    }

    private List<VariableSymbol> BindParameters(ParameterListContext list, VariableKind kind, MacroContext context)
    {
        var result = new List<VariableSymbol>();
        foreach (var p in list.parameter())
        {
            var name = p.name().GetText();
            if (context.Variables.TryGetValue(name, out var existing))
            {
                _diagnostics.ReportDuplicate(Span(p.name()), kind == VariableKind.Input ? "input" : "output", name, existing.Declaration);
                continue;
            }
            var cls = LookupMember<MultivectorClassSymbol>(p.qualifiedName(), "multivector class");
            var variable = new VariableSymbol(name, Span(p.name()), kind) { Class = cls, Frame = cls?.Frame };
            context.Variables[name] = variable;
            context.Types[variable] = cls is null ? new ExpressionType(null, 0) : new ExpressionType(cls.Frame, cls.GradeMask);
            if (kind == VariableKind.Input) context.Assigned.Add(variable);
            result.Add(variable);
        }
        return result;
    }

    private void BindMacroBody(MacroDefinitionContext syntax, MacroSymbol macro)
    {
        var context = _macroContexts[macro];
        var scope = new Scope(context);
        var statements = new List<BoundStatement>();
        foreach (var statement in syntax.statement())
            if (BindStatement(statement, scope, context) is { } bound) statements.Add(bound);
        macro.Statements = statements;
        macro.LiveStatements = Liveness.Of(statements, macro.Outputs);
        macro.Temporaries = context.Temporaries;
        macro.Callees = context.Callees.ToList();

        foreach (var output in macro.Outputs.Where(o => !context.Assigned.Contains(o)))
            _diagnostics.ReportOutputNeverAssigned(output.Declaration, macro.Name, output.Name);
        foreach (var temp in context.Temporaries.Where(t => !t.IsReferenced))
            _diagnostics.ReportUnused(temp.Declaration, "temporary", temp.Name);
    }

    private BoundStatement? BindStatement(StatementContext syntax, Scope scope, MacroContext context)
    {
        var span = Span(syntax);
        switch (syntax)
        {
            case AssignmentStatementContext a:
            {
                var value = BindExpression(a.expr(), scope);
                var target = AssignTarget(a.name().GetText(), Span(a.name()), value?.Type, context);
                return value is null || target is null ? null : new BoundAssignment(target, value, span);
            }
            case CallStatementContext c:
                return BindCallStatement(c, scope, context, span);
            case OutputStatementContext o:
                return BindOutputStatement(o, scope, span);
            case JoinStatementContext j:
                return new BoundJoinStatement(j.ON() is not null, span);
            default:
                return null;
        }
    }

    /// <summary>Checks an assignment target and records its new type; null when it cannot be assigned.</summary>
    private VariableSymbol? AssignTarget(string name, SourceSpan span, ExpressionType? type, MacroContext context)
    {
        if (context.Variables.TryGetValue(name, out var variable))
        {
            if (variable.Kind == VariableKind.Input)
            {
                _diagnostics.ReportAssignToInput(span, name);
                return null;
            }
            // An output assigned a value that has errors still counts as assigned: those errors are
            // reported already, and "never assigned" would be false.
            if (variable.Kind == VariableKind.Output) context.Assigned.Add(variable);
            if (type is not { } t) return null;
            if (variable.Kind == VariableKind.Output)
            {
                if (variable.Class is not { } cls) return null;
                if (t.Frame is { } frame && frame != cls.Frame)
                {
                    _diagnostics.ReportOutputClassMismatch(span, name, cls.QualifiedName, $"the value belongs to frame '{frame.Name}'");
                    return null;
                }
                if ((t.GradeMask & cls.GradeMask) == 0 && t.GradeMask != 0)
                {
                    _diagnostics.ReportOutputClassMismatch(span, name, cls.QualifiedName,
                        $"the value has grades {Grades(t.GradeMask)} but the class holds grades {Grades(cls.GradeMask)}");
                    return null;
                }
                return variable;
            }
            var old = context.Types[variable];
            if (old.Frame != t.Frame && old.Frame is not null && t.Frame is not null)
            {
                _diagnostics.ReportFrameMismatch(span, old.Frame.Name, t.Frame.Name);
                return null;
            }
            context.Types[variable] = new ExpressionType(t.Frame ?? old.Frame, t.GradeMask);
            variable.Frame = t.Frame ?? old.Frame;
            return variable;
        }
        if (type is not { } newType) return null;
        var temp = new VariableSymbol(name, span, VariableKind.Temporary) { Frame = newType.Frame };
        context.Variables[name] = temp;
        context.Types[temp] = newType;
        context.Assigned.Add(temp);
        context.Temporaries.Add(temp);
        return temp;
    }

    private static string Grades(int mask) =>
        "{" + string.Join(", ", Enumerable.Range(0, 32).Where(g => (mask & (1 << g)) != 0)) + "}";

    private MacroSymbol? LookupMacro(NameContext name, MacroContext context)
    {
        var text = name.GetText();
        if (_macros.TryGetValue(text, out var macro))
        {
            macro.IsReferenced = true;
            context.Callees.Add(macro);
            return macro;
        }
        ReportUnknown(Span(name), "macro", text, _macros.Keys);
        return null;
    }

    private BoundStatement? BindCallStatement(CallStatementContext c, Scope scope, MacroContext context, SourceSpan span)
    {
        if (LookupMacro(c.name(), context) is not { } callee)
        {
            // The outputs named as arguments are meant to be assigned here; the unknown macro is the error.
            foreach (var arg in c.callArgument())
                if (arg.expr() is NameExprContext n && context.Variables.TryGetValue(n.GetText(), out var v) && v.Kind == VariableKind.Output)
                    context.Assigned.Add(v);
            return null;
        }
        var bindings = new List<BoundCallBinding>();
        var ok = true;
        foreach (var arg in c.callArgument())
        {
            var parameterName = arg.name().GetText();
            var parameter = callee.Inputs.Concat(callee.Outputs).FirstOrDefault(v => v.Name == parameterName);
            if (parameter is null)
            {
                ReportUnknown(Span(arg.name()), $"input or output of macro '{callee.Name}'", parameterName,
                    callee.Inputs.Concat(callee.Outputs).Select(v => v.Name));
                ok = false;
                continue;
            }
            if (bindings.Any(b => b.Parameter == parameter))
            {
                _diagnostics.ReportDuplicate(Span(arg.name()), "binding", parameterName, span);
                ok = false;
                continue;
            }
            if (parameter.Kind == VariableKind.Input)
            {
                var value = BindExpression(arg.expr(), scope);
                if (value is null || !CheckArgumentFrame(value, parameter, Span(arg.expr()))) { ok = false; continue; }
                bindings.Add(new BoundCallBinding(parameter, value, null));
            }
            else
            {
                if (arg.expr() is not NameExprContext { } targetName || targetName.qualifiedName().name().Length != 1)
                {
                    _diagnostics.ReportCallError(Span(arg.expr()), $"output '{parameterName}' must be bound to a multivector name");
                    ok = false;
                    continue;
                }
                var paramType = parameter.Class is { } pc ? new ExpressionType(pc.Frame, pc.GradeMask) : (ExpressionType?)null;
                var target = AssignTarget(targetName.GetText(), Span(targetName), paramType, context);
                if (target is null) { ok = false; continue; }
                bindings.Add(new BoundCallBinding(parameter, null, target));
            }
        }
        foreach (var missing in callee.Inputs.Where(i => bindings.All(b => b.Parameter != i)))
        {
            _diagnostics.ReportCallError(span, $"input '{missing.Name}' of macro '{callee.Name}' is not bound");
            ok = false;
        }
        return ok ? new BoundCallStatement(callee, bindings, span) : null;
    }

    private bool CheckArgumentFrame(BoundExpression value, VariableSymbol parameter, SourceSpan span)
    {
        if (parameter.Frame is { } frame && value.Type.Frame is { } actual && actual != frame)
        {
            _diagnostics.ReportFrameMismatch(span, frame.Name, actual.Name);
            return false;
        }
        return true;
    }

    private static readonly Regex OutputReference = new(@"<\s*([A-Za-z_][A-Za-z_0-9]*)\s*\.\s*([A-Za-z_0-9^\s]+?)\s*>", RegexOptions.CultureInvariant);

    private BoundStatement BindOutputStatement(OutputStatementContext o, Scope scope, SourceSpan span)
    {
        var raw = o.OUTPUT_BLOCK().GetText();
        var open = raw.IndexOf('{');
        var text = raw[(open + 1)..^1];
        // The one reading of the <mv.blade> references: the generator and the host's check of the
        // text take these parts, not the text.
        var parts = new List<OutputPart>();
        var last = 0;
        foreach (Match match in OutputReference.Matches(text))
        {
            if (match.Index > last) parts.Add(new OutputTextPart(text[last..match.Index]));
            last = match.Index + match.Length;
            parts.Add(new OutputReferencePart(match.Value, BindOutputReference(match, scope, span)));
        }
        if (last < text.Length) parts.Add(new OutputTextPart(text[last..]));
        return new BoundOutputStatement(parts, span.Offset(raw, open + 1), span);
    }

    private BoundCoefficient? BindOutputReference(Match match, Scope scope, SourceSpan span)
    {
        if (scope.Macro!.Read(match.Groups[1].Value, span) is not { } operand) return null;
        if (operand.Type.Frame is not { } frame)
        {
            _diagnostics.ReportTypeError(span, $"'{match.Groups[1].Value}' is a scalar and has no blade coefficients");
            return null;
        }
        return ParseBladeText(match.Groups[2].Value, frame, span) is { } b ? new BoundCoefficient(operand, b, span) : null;
    }

    private BladeReference? ParseBladeText(string text, FrameSymbol frame, SourceSpan span)
    {
        var parts = text.Split('^', StringSplitOptions.TrimEntries);
        if (parts is ["1"]) return new BladeReference(0, 1);
        var mask = 0;
        var sign = 1;
        foreach (var part in parts)
        {
            var index = frame.IndexOfBasis(part);
            if (index < 0 || (mask & (1 << index)) != 0)
            {
                ReportUnknown(span, $"blade of frame '{frame.Name}'", text.Trim(), frame.BasisNames);
                return null;
            }
            if ((System.Numerics.BitOperations.PopCount((uint)(mask & ~((2 << index) - 1))) & 1) == 1) sign = -sign;
            mask |= 1 << index;
        }
        return new BladeReference(mask, sign);
    }

    // ------------------------------------------------------------------ built-in operators and macro calls

    private BoundExpression? BindMacroScopeCall(CallExprContext call, string name, ExprContext[] args, Scope scope, SourceSpan span)
    {
        var context = scope.Macro!;
        BoundExpression? Multivector(int index)
        {
            var e = BindExpression(args[index], scope);
            if (e is null) return null;
            if (e.Type.Frame is null)
            {
                _diagnostics.ReportTypeError(Span(args[index]), $"'{name}' needs a multivector operand, not a scalar");
                return null;
            }
            return e;
        }
        bool Arity(int count)
        {
            if (args.Length == count) return true;
            _diagnostics.ReportTypeError(span, $"'{name}' takes {count} argument(s), not {args.Length}");
            return false;
        }

        if (UnaryOperators.TryGetValue(name, out var unary))
        {
            if (!Arity(1) || Multivector(0) is not { } operand) return null;
            var frame = operand.Type.Frame!;
            var n = frame.Dimension;
            // A⌋I⁻¹ needs I invertible; with a null basis vector it is not, and the complement is what works.
            if (unary is UnaryOperator.Dual or UnaryOperator.Undual && frame.InnerProductMatrix.Determinant().IsZero)
            {
                _diagnostics.ReportNoDual(span, name, frame.Name);
                return null;
            }
            if (unary is UnaryOperator.GeneralInverse && n > GMac.Core.Algebra.Multivector<double>.GeneralInverseMaxDimension)
            {
                _diagnostics.ReportGeneralInverseTooLarge(span, frame.Name, n);
                return null;
            }
            var grades = unary switch
            {
                UnaryOperator.Norm or UnaryOperator.Norm2 or UnaryOperator.QuasiNorm or UnaryOperator.QuasiNorm2 => 1,
                UnaryOperator.Dual or UnaryOperator.Undual or UnaryOperator.RightComplement or UnaryOperator.LeftComplement => Enumerable.Range(0, n + 1)
                    .Where(g => (operand.Type.GradeMask & (1 << g)) != 0).Aggregate(0, (m, g) => m | (1 << (n - g))),
                // The adjugate keeps the even subalgebra and the span of 1 and the vectors; other operands fill every grade.
                UnaryOperator.GeneralInverse => (operand.Type.GradeMask & ~0b11) == 0 || (operand.Type.GradeMask & 0x2AAAAAAA) == 0
                    ? operand.Type.GradeMask
                    : AllGrades(frame),
                _ => operand.Type.GradeMask,
            };
            return new BoundUnaryOperation(unary, operand, new ExpressionType(frame, grades), span);
        }

        switch (name)
        {
            case "exp":
            {
                if (!Arity(1) || BindExpression(args[0], scope) is not { } operand) return null;
                if (operand.Type.Frame is not { } frame)
                    return new BoundScalarFunctionCall(ScalarFunction.Exp, [operand], span);
                var even = Enumerable.Range(0, frame.Dimension + 1).Where(g => g % 2 == 0).Aggregate(0, (m, g) => m | (1 << g));
                var grades = (operand.Type.GradeMask & ~even) == 0 ? even : AllGrades(frame);
                return new BoundUnaryOperation(UnaryOperator.Exp, operand, new ExpressionType(frame, grades), span);
            }
            case "grade":
            {
                if (!Arity(2) || Multivector(0) is not { } operand) return null;
                if (EvaluateInteger(args[1], "a grade") is not { } k) return null;
                if (k < 0 || k > operand.Type.Frame!.Dimension)
                {
                    _diagnostics.ReportTypeError(Span(args[1]), $"grade {k} does not exist in frame '{operand.Type.Frame!.Name}'");
                    return null;
                }
                return new BoundGradeProjection(operand, k, new ExpressionType(operand.Type.Frame, 1 << k), span);
            }
            case "apply":
            {
                if (!Arity(2) || Multivector(0) is not { } versor || BindExpression(args[1], scope) is not { } operand) return null;
                if (Combine(versor, operand, span) is not { } frame) return null;
                var grades = operand.Type.IsScalar ? 1 : operand.Type.GradeMask;
                return new BoundVersorApplication(versor, operand, new ExpressionType(frame, grades), span);
            }
            case "scale" or "div_by_scalar":
            {
                if (!Arity(2) || Multivector(0) is not { } operand || BindExpression(args[1], scope) is not { } factor) return null;
                if (!IsScalarValued(factor))
                {
                    _diagnostics.ReportTypeError(Span(args[1]), $"the second operand of '{name}' must be a scalar");
                    return null;
                }
                if (factor.Type.Frame is not null && Combine(operand, factor, span) is null) return null;
                return CheckConstant(new BoundBinaryOperation(name == "scale" ? BinaryOperator.Multiply : BinaryOperator.Divide,
                    operand, factor, operand.Type, span), () => $"{name}(...)", args[1].GetText);
            }
            case "diff":
            {
                if (!Arity(2) || Multivector(0) is not { } operand || BindExpression(args[1], scope) is not { } variable) return null;
                var coefficient = variable switch
                {
                    BoundCoefficient c => c,
                    BoundVariableReference { Type.Frame: not null, Type.GradeMask: 1 } v => new BoundCoefficient(v, new BladeReference(0, 1), v.Span),
                    _ => null,
                };
                if (coefficient is null || coefficient.Operand is not BoundVariableReference)
                {
                    _diagnostics.ReportTypeError(Span(args[1]), "'diff' differentiates with respect to a coefficient such as t.<1>");
                    return null;
                }
                return new BoundDifferentiation(operand, coefficient, operand.Type, span);
            }
            case "cast_to_grades":
            {
                if (args.Length < 2) { Arity(2); return null; }
                if (Multivector(0) is not { } operand) return null;
                var frame = operand.Type.Frame!;
                var mask = 0;
                var fromModel = false;
                // Thesis form: the grades of another multivector, cast_to_grades(A, B).
                if (args.Length == 2 && args[1] is NameExprContext other && other.qualifiedName().name().Length == 1
                    && context.Variables.ContainsKey(other.GetText()))
                {
                    if (BindExpression(args[1], scope) is not { } model) return null;
                    if (model.Type.Frame is { } f && f != frame)
                    {
                        _diagnostics.ReportFrameMismatch(span, frame.Name, f.Name);
                        return null;
                    }
                    mask = model.Type.GradeMask;
                    fromModel = true;
                }
                for (var i = 1; i < args.Length && !fromModel; i++)
                {
                    if (EvaluateInteger(args[i], "a grade") is not { } k) return null;
                    if (k < 0 || k > frame.Dimension)
                    {
                        _diagnostics.ReportTypeError(Span(args[i]), $"grade {k} does not exist in frame '{frame.Name}'");
                        return null;
                    }
                    mask |= 1 << k;
                }
                var blades = Enumerable.Range(0, 1 << frame.Dimension)
                    .Where(b => (mask & (1 << System.Numerics.BitOperations.PopCount((uint)b))) != 0).ToList();
                return new BoundCast(CastKind.ToGrades, operand, blades, null, new ExpressionType(frame, mask), span);
            }
            case "cast_to_subspace" or "cast_to_class":
            {
                if (!Arity(2) || Multivector(0) is not { } operand) return null;
                var frame = operand.Type.Frame!;
                if (args[1] is not NameExprContext target)
                {
                    _diagnostics.ReportTypeError(Span(args[1]), $"the second operand of '{name}' is a {(name == "cast_to_class" ? "class" : "subspace")} name");
                    return null;
                }
                Symbol? symbol = name == "cast_to_class"
                    ? LookupMember<MultivectorClassSymbol>(target.qualifiedName(), "multivector class", frame)
                    : LookupMember<SubspaceSymbol>(target.qualifiedName(), "subspace", frame);
                var (targetFrame, blades) = symbol switch
                {
                    MultivectorClassSymbol c => (c.Frame, c.AllBlades.ToList()),
                    SubspaceSymbol s => (s.Frame, s.Blades.ToList()),
                    _ => (null, []),
                };
                if (targetFrame is null) return null;
                if (targetFrame != frame)
                {
                    _diagnostics.ReportFrameMismatch(span, frame.Name, targetFrame.Name);
                    return null;
                }
                var grades = blades.Aggregate(0, (m, b) => m | (1 << System.Numerics.BitOperations.PopCount((uint)b)));
                return new BoundCast(name == "cast_to_class" ? CastKind.ToClass : CastKind.ToSubspace, operand, blades, symbol,
                    new ExpressionType(frame, grades), span);
            }
        }

        if (call.qualifiedName().name().Length == 1 && _macros.TryGetValue(name, out var macro))
        {
            macro.IsReferenced = true;
            context.Callees.Add(macro);
            if (macro.Outputs.Count != 1)
            {
                _diagnostics.ReportCallError(span, $"macro '{name}' has {macro.Outputs.Count} outputs; use 'call {name} {{ … }}' instead");
                return null;
            }
            if (args.Length != macro.Inputs.Count)
            {
                _diagnostics.ReportCallError(span, $"macro '{name}' takes {macro.Inputs.Count} input(s), not {args.Length}");
                return null;
            }
            var bound = new List<BoundExpression>();
            for (var i = 0; i < args.Length; i++)
            {
                if (BindExpression(args[i], scope) is not { } value || !CheckArgumentFrame(value, macro.Inputs[i], Span(args[i]))) return null;
                bound.Add(value);
            }
            var cls = macro.Outputs[0].Class;
            return cls is null ? null : new BoundMacroCall(macro, bound, new ExpressionType(cls.Frame, cls.GradeMask), span);
        }

        ReportUnknown(Span(call.qualifiedName()), "function or macro", name,
            ScalarFunctions.Keys.Concat(UnaryOperators.Keys).Concat(OtherBuiltins).Concat(_macros.Keys));
        return null;
    }
}
