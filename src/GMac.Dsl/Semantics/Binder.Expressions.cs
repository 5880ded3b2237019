using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;
using static GMac.Dsl.Syntax.Generated.GMacDslParser;

namespace GMac.Dsl.Semantics;

internal sealed partial class Binder
{
    /// <summary>Where an expression appears decides which names it may use.</summary>
    private sealed class Scope
    {
        public static readonly Scope Constant = new(null);
        public static readonly Scope Binding = new(null) { AllowsMembers = true };

        public Scope(MacroContext? macro) => Macro = macro;

        public MacroContext? Macro { get; }
        public bool AllowsMembers { get; private init; }
    }

    private static readonly Dictionary<string, (ScalarFunction Function, int Arity)> ScalarFunctions = new()
    {
        ["sin"] = (ScalarFunction.Sin, 1), ["cos"] = (ScalarFunction.Cos, 1), ["tan"] = (ScalarFunction.Tan, 1),
        ["asin"] = (ScalarFunction.Asin, 1), ["acos"] = (ScalarFunction.Acos, 1), ["atan"] = (ScalarFunction.Atan, 1),
        ["atan2"] = (ScalarFunction.Atan2, 2), ["sinh"] = (ScalarFunction.Sinh, 1), ["cosh"] = (ScalarFunction.Cosh, 1),
        ["tanh"] = (ScalarFunction.Tanh, 1), ["sqrt"] = (ScalarFunction.Sqrt, 1), ["log"] = (ScalarFunction.Log, 1),
        ["abs"] = (ScalarFunction.Abs, 1),
    };

    private static readonly Dictionary<string, UnaryOperator> UnaryOperators = new()
    {
        ["reverse"] = UnaryOperator.Reverse, ["grade_inv"] = UnaryOperator.GradeInvolution,
        ["cliff_conj"] = UnaryOperator.CliffordConjugate, ["inverse"] = UnaryOperator.Inverse,
        ["general_inverse"] = UnaryOperator.GeneralInverse,
        ["dual"] = UnaryOperator.Dual, ["undual"] = UnaryOperator.Undual, ["norm"] = UnaryOperator.Norm,
        ["rcomplement"] = UnaryOperator.RightComplement, ["lcomplement"] = UnaryOperator.LeftComplement,
        ["norm2"] = UnaryOperator.Norm2, ["quasi_norm"] = UnaryOperator.QuasiNorm, ["quasi_norm2"] = UnaryOperator.QuasiNorm2,
    };

    private static readonly string[] OtherBuiltins =
        ["exp", "grade", "apply", "scale", "div_by_scalar", "diff", "cast_to_grades", "cast_to_subspace", "cast_to_class", "pi"];

    /// <summary>Every name a macro can call as a built-in function or operator (documented in docs/language.md; a test keeps them there).</summary>
    internal static IEnumerable<string> BuiltinNames => ScalarFunctions.Keys.Concat(UnaryOperators.Keys).Concat(OtherBuiltins).Distinct(StringComparer.Ordinal);

    private static int AllGrades(FrameSymbol frame) => (1 << (frame.Dimension + 1)) - 1;

    private BoundExpression? BindExpression(ExprContext syntax, Scope scope)
    {
        var span = Span(syntax);
        switch (syntax)
        {
            case ParenExprContext p:
                return BindExpression(p.expr(), scope);
            case PlusExprContext plus:
                return BindExpression(plus.expr(), scope);
            case NumberExprContext n:
                return BindNumber(n, span);
            case NegateExprContext neg:
                return BindExpression(neg.expr(), scope) is { } operand
                    ? new BoundUnaryOperation(UnaryOperator.Negate, operand, operand.Type, span)
                    : null;
            case MemberExprContext m:
                if (scope.AllowsMembers)
                    return new BoundMemberReference(string.Join(".", m.memberReference().name().Select(x => x.GetText())), span);
                _diagnostics.ReportInvalidScalar(span, "member references like <x> belong in class bindings; use A.<blade> for a coefficient");
                return null;
            case PowerExprContext pw:
            {
                var (l, r) = (BindExpression(pw.expr(0), scope), BindExpression(pw.expr(1), scope));
                if (l is null || r is null) return null;
                if (!l.Type.IsScalar || !r.Type.IsScalar)
                {
                    _diagnostics.ReportTypeError(span, "'^' raises a scalar to a power; use 'op' for the outer product");
                    return null;
                }
                return CheckConstant(new BoundBinaryOperation(BinaryOperator.Power, l, r, ExpressionType.Scalar, span), pw.GetText);
            }
            case ScaleExprContext s:
                return BindScale(s, scope, span);
            case ProductExprContext p:
                return BindProduct(p, scope, span);
            case SumExprContext s:
                return BindSum(s, scope);
            case CoefficientExprContext c:
                return BindCoefficient(c, scope, span);
            case NameExprContext n:
                return BindName(n.qualifiedName(), scope, span);
            case CallExprContext call:
                return BindCall(call, scope, span);
            case TransformExprContext t:
                return BindTransformApplication(t, scope, span);
            case MultivectorExprContext mv:
            {
                if (scope.Macro is null)
                {
                    _diagnostics.ReportInvalidScalar(span, "a multivector cannot appear in a scalar expression");
                    return null;
                }
                if (LookupFrame(mv.name()) is not { } frame) return null;
                var coefficients = BindCoefficientList(mv.coefficientList(), frame, scope);
                var grades = coefficients.Aggregate(0, (g, c) => g | (1 << c.Blade.Grade));
                return new BoundMultivectorConstruction(frame, coefficients, new ExpressionType(frame, grades), span);
            }
            default:
                _diagnostics.ReportSyntaxError(span, $"unexpected expression '{syntax.GetText()}'");
                return null;
        }
    }

    /// <summary>Sums of this many operators or more are bound as a balanced tree; shorter ones left to right.</summary>
    private const int LongSum = 64;

    /// <summary>
    /// A chain a ± b ± c …, which parses as a tree as deep as the chain is long. Its operands are
    /// collected without recursion; a short chain is bound left to right as written, a long one as a
    /// balanced tree (the same sum, exact in the symbolic engine) so that later stages, which recurse
    /// over bound trees, go only logarithmically deep.
    /// </summary>
    private BoundExpression? BindSum(SumExprContext syntax, Scope scope)
    {
        var sums = new List<SumExprContext>();
        ExprContext node = syntax;
        while (node is SumExprContext s)
        {
            sums.Add(s);
            node = s.expr(0);
        }
        sums.Reverse(); // innermost (leftmost) first
        var first = BindExpression(node, scope);
        if (sums.Count < LongSum)
        {
            var result = first;
            foreach (var s in sums)
            {
                var right = BindExpression(s.expr(1), scope);
                result = result is null || right is null ? null : Add(result, right, IsMinus(s), Span(s));
            }
            return result;
        }
        var operands = new List<(BoundExpression? Value, bool Negated)>(sums.Count + 1) { (first, false) };
        foreach (var s in sums) operands.Add((BindExpression(s.expr(1), scope), IsMinus(s)));
        return operands.Any(o => o.Value is null) ? null : Balanced(operands, 0, operands.Count);

        static bool IsMinus(SumExprContext s) => s.op.Type == Syntax.Generated.GMacDslLexer.MINUS;
    }

    /// <summary>
    /// The operands [start, end) summed with the sign of each relative to the first one's: splitting at
    /// m, it is the left half plus or minus the right half as their first signs agree or not.
    /// </summary>
    private BoundExpression? Balanced(List<(BoundExpression? Value, bool Negated)> operands, int start, int end)
    {
        if (end - start == 1) return operands[start].Value;
        var middle = (start + end) / 2;
        var left = Balanced(operands, start, middle);
        var right = Balanced(operands, middle, end);
        if (left is null || right is null) return null;
        var (head, tail) = (left.Span, right.Span);
        var span = head with { Length = Math.Max(0, tail.Start + tail.Length - head.Start) };
        return Add(left, right, operands[middle].Negated != operands[start].Negated, span);
    }

    private BoundExpression? Add(BoundExpression l, BoundExpression r, bool subtract, SourceSpan span)
    {
        if (Combine(l, r, span) is null && !(l.Type.IsScalar && r.Type.IsScalar)) return null;
        var type = l.Type.IsScalar && r.Type.IsScalar
            ? ExpressionType.Scalar
            : new ExpressionType(l.Type.Frame ?? r.Type.Frame, l.Type.GradeMask | r.Type.GradeMask);
        return new BoundBinaryOperation(subtract ? BinaryOperator.Subtract : BinaryOperator.Add, l, r, type, span);
    }

    private BoundExpression? BindNumber(NumberExprContext n, SourceSpan span)
    {
        var text = n.number().GetText();
        var e = text.IndexOfAny(['e', 'E']);
        if (e >= 0 && (!int.TryParse(text[(e + 1)..], out var exponent) || Math.Abs(exponent) > 300))
        {
            _diagnostics.ReportInvalidScalar(span, $"number '{text}' is out of range");
            return null;
        }
        if (text.Length > 400)
        {
            _diagnostics.ReportInvalidScalar(span, "number literal is too long");
            return null;
        }
        return new BoundNumber(Rational.Parse(text), span);
    }

    /// <summary>Frame of a combination of two operands, or null (reported) if they disagree.</summary>
    private FrameSymbol? Combine(BoundExpression l, BoundExpression r, SourceSpan span)
    {
        var (a, b) = (l.Type.Frame, r.Type.Frame);
        if (a is not null && b is not null && a != b)
        {
            _diagnostics.ReportFrameMismatch(span, a.Name, b.Name);
            return null;
        }
        return a ?? b;
    }

    /// <summary>
    /// Reports a division by a constant zero, or a constant operation with finite operands and no
    /// finite real value (sqrt(-4), log(0), asin(2), 0^-1): generated code would compute NaN or
    /// infinity. Null when reported.
    /// </summary>
    /// <param name="text">The expression's text, read only for a message: reading it costs its length.</param>
    private BoundExpression? CheckConstant(BoundExpression e, Func<string> text, Func<string>? divisorText = null)
    {
        if (e is BoundBinaryOperation { Operator: BinaryOperator.Divide } d)
        {
            if (NumericFolding.TryEvaluate(d.Right) is 0)
            {
                _diagnostics.ReportDivisionByZero(e.Span, (divisorText ?? text)());
                return null;
            }
            if (!d.Type.IsScalar) return e;
        }
        if (NumericFolding.TryEvaluate(e) is { } value && !double.IsFinite(value) && OperandsAreFinite(e) && !IsPowerOverflow(e, value))
        {
            _diagnostics.ReportNoRealValue(e.Span, text(), value);
            return null;
        }
        return e;
    }

    /// <summary>A power too large for a double but exact as a rational (2^64)^64 is not a missing value.</summary>
    private static bool IsPowerOverflow(BoundExpression e, double value) =>
        e is BoundBinaryOperation { Operator: BinaryOperator.Power } p && !double.IsNaN(value) && NumericFolding.TryEvaluate(p.Left) is not 0.0;

    private static bool OperandsAreFinite(BoundExpression e) =>
        (e switch
        {
            BoundBinaryOperation b => [b.Left, b.Right],
            BoundScalarFunctionCall c => c.Arguments,
            _ => (IReadOnlyList<BoundExpression>)[],
        }).All(o => NumericFolding.TryEvaluate(o) is { } v && double.IsFinite(v));

    private static bool IsScalarValued(BoundExpression e) => e.Type.IsScalar || e.Type.GradeMask == 1;

    private BoundExpression? BindScale(ScaleExprContext s, Scope scope, SourceSpan span)
    {
        var (l, r) = (BindExpression(s.expr(0), scope), BindExpression(s.expr(1), scope));
        if (l is null || r is null) return null;
        var divide = s.op.Type == Syntax.Generated.GMacDslLexer.SLASH;
        if (divide ? !IsScalarValued(r) : !IsScalarValued(l) && !IsScalarValued(r))
        {
            _diagnostics.ReportTypeError(span, divide
                ? "can only divide by a scalar; multiply by inverse(...) instead"
                : "'*' needs a scalar factor; use 'gp' for the geometric product");
            return null;
        }
        if (l.Type.Frame is not null && r.Type.Frame is not null && Combine(l, r, span) is null) return null;
        var type = l.Type.IsScalar && r.Type.IsScalar
            ? ExpressionType.Scalar
            : IsScalarValued(l) && !l.Type.IsScalar && IsScalarValued(r) ? l.Type
            : IsScalarValued(l) ? r.Type with { Frame = r.Type.Frame ?? l.Type.Frame } : l.Type;
        return CheckConstant(new BoundBinaryOperation(divide ? BinaryOperator.Divide : BinaryOperator.Multiply, l, r, type, span), s.GetText, s.expr(1).GetText);
    }

    private BoundExpression? BindProduct(ProductExprContext p, Scope scope, SourceSpan span)
    {
        var (l, r) = (BindExpression(p.expr(0), scope), BindExpression(p.expr(1), scope));
        if (l is null || r is null) return null;
        var op = p.op.Text switch
        {
            "gp" => BinaryOperator.Gp, "op" => BinaryOperator.Op, "sp" => BinaryOperator.Sp,
            "lcp" => BinaryOperator.Lcp, "rcp" => BinaryOperator.Rcp, "fdp" => BinaryOperator.Fdp,
            "hip" => BinaryOperator.Hip, "cp" => BinaryOperator.Cp, "vee" => BinaryOperator.Vee, _ => BinaryOperator.Acp,
        };
        var frame = Combine(l, r, span);
        if (frame is null)
        {
            if (l.Type.Frame is not null || r.Type.Frame is not null) return null;
            _diagnostics.ReportTypeError(span, $"'{p.op.Text}' needs a multivector operand");
            return null;
        }
        return new BoundBinaryOperation(op, l, r, new ExpressionType(frame, ProductGrades(op, l.Type.GradeMask, r.Type.GradeMask, frame.Dimension)), span);
    }

    /// <summary>Grades a product may produce, from the grades of its operands (metric independent bound).</summary>
    internal static int ProductGrades(BinaryOperator op, int left, int right, int n)
    {
        var result = 0;
        for (var a = 0; a <= n; a++)
        {
            if ((left & (1 << a)) == 0) continue;
            for (var b = 0; b <= n; b++)
            {
                if ((right & (1 << b)) == 0) continue;
                switch (op)
                {
                    case BinaryOperator.Op: if (a + b <= n) result |= 1 << (a + b); break;
                    case BinaryOperator.Sp: result |= a == b ? 1 : 0; break;
                    case BinaryOperator.Lcp: if (b >= a) result |= 1 << (b - a); break;
                    case BinaryOperator.Rcp: if (a >= b) result |= 1 << (a - b); break;
                    case BinaryOperator.Fdp: result |= 1 << Math.Abs(a - b); break;
                    case BinaryOperator.Hip: if (a > 0 && b > 0) result |= 1 << Math.Abs(a - b); break;
                    case BinaryOperator.Vee: if (a + b >= n) result |= 1 << (a + b - n); break;
                    default:
                        for (var g = Math.Abs(a - b); g <= Math.Min(a + b, n); g += 2) result |= 1 << g;
                        break;
                }
            }
        }
        return result;
    }

    private BoundExpression? BindCoefficient(CoefficientExprContext c, Scope scope, SourceSpan span)
    {
        if (BindExpression(c.expr(), scope) is not { } operand) return null;
        if (operand.Type.Frame is not { } frame)
        {
            if (c.bladeName().GetText() == "1") return operand;
            _diagnostics.ReportTypeError(span, "a scalar has only the coefficient <1>");
            return null;
        }
        return BindBlade(c.bladeName(), frame) is { } blade ? new BoundCoefficient(operand, blade, span) : null;
    }

    private BoundExpression? BindName(QualifiedNameContext qualified, Scope scope, SourceSpan span)
    {
        var parts = qualified.name();
        if (parts.Length == 1)
        {
            var name = parts[0].GetText();
            if (name == "pi") return new BoundScalarFunctionCall(ScalarFunction.Pi, [], span);
            if (scope.Macro is { } macro)
                return macro.Read(name, span);
            ReportUnknown(span, "name", name, ["pi"]);
            return null;
        }
        if (parts.Length == 2 && scope.Macro is not null)
        {
            if (LookupFrame(parts[0]) is not { } frame) return null;
            var member = parts[1].GetText();
            if (frame.Members.TryGetValue(member, out var symbol))
            {
                if (symbol is ConstantSymbol constant)
                {
                    constant.IsReferenced = true;
                    var grades = constant.Coefficients.Aggregate(0, (g, c) => g | (1 << c.Blade.Grade));
                    return new BoundConstantReference(constant, new ExpressionType(frame, grades), span);
                }
                _diagnostics.ReportWrongKind(span, qualified.GetText(), KindOf(symbol), "a multivector value");
                return null;
            }
            var index = frame.IndexOfBasis(member);
            if (index >= 0)
                return new BoundMultivectorConstruction(frame,
                    [new CoefficientValue(new BladeReference(1 << index, 1), new BoundNumber(Rational.One, span))],
                    new ExpressionType(frame, 2), span);
            ReportUnknown(span, "constant or basis vector", qualified.GetText(),
                frame.MemberSymbols.OfType<ConstantSymbol>().Select(k => $"{frame.Name}.{k.Name}")
                    .Concat(frame.BasisNames.Select(b => $"{frame.Name}.{b}")));
            return null;
        }
        if (scope.Macro is null)
            _diagnostics.ReportInvalidScalar(span, $"'{qualified.GetText()}' cannot be used in a constant scalar expression");
        else
            _diagnostics.ReportTypeError(span, $"'{qualified.GetText()}' is not a valid name here");
        return null;
    }

    private BoundExpression? BindTransformApplication(TransformExprContext t, Scope scope, SourceSpan span)
    {
        var name = t.qualifiedName().GetText();
        if (scope.Macro is null)
        {
            _diagnostics.ReportInvalidScalar(span, "a linear transform cannot appear in a scalar expression");
            return null;
        }
        if (!_transforms.TryGetValue(name, out var transform))
        {
            ReportUnknown(Span(t.qualifiedName()), "transform", name, _transforms.Keys);
            return null;
        }
        transform.IsReferenced = true;
        if (BindExpression(t.expr(), scope) is not { } operand) return null;
        if (operand.Type.Frame is { } frame && frame != transform.Source)
        {
            _diagnostics.ReportFrameMismatch(span, transform.Source.Name, frame.Name);
            return null;
        }
        var grades = operand.Type.IsScalar ? 1 : operand.Type.GradeMask;
        return new BoundTransformApplication(transform, operand, new ExpressionType(transform.Destination, grades), span);
    }

    /// <summary>log(M) is a bivector, sqrt(R) has the grades of R and a scalar; both need even grades.</summary>
    private BoundUnaryOperation? BindVersorFunction(string name, BoundExpression operand, FrameSymbol frame, ExpressionType type, SourceSpan span)
    {
        var odd = Enumerable.Range(0, frame.Dimension + 1).Where(g => g % 2 == 1).Aggregate(0, (m, g) => m | (1 << g));
        if ((type.GradeMask & odd) != 0)
        {
            _diagnostics.ReportTypeError(span, $"'{name}' of a multivector takes a rotor or motor (even grades); this operand has odd grades");
            return null;
        }
        return name == "log"
            ? new BoundUnaryOperation(UnaryOperator.Log, operand, new ExpressionType(frame, 1 << 2), span)
            : new BoundUnaryOperation(UnaryOperator.VersorSqrt, operand, new ExpressionType(frame, type.GradeMask | 1), span);
    }

    private BoundExpression? BindCall(CallExprContext call, Scope scope, SourceSpan span)
    {
        var name = call.qualifiedName().GetText();
        var args = call.expr();

        if (ScalarFunctions.TryGetValue(name, out var fn) || (name == "exp" && scope.Macro is null))
        {
            if (name == "exp") fn = (ScalarFunction.Exp, 1);
            if (args.Length != fn.Arity)
            {
                _diagnostics.ReportInvalidScalar(span, $"'{name}' takes {fn.Arity} argument(s), not {args.Length}");
                return null;
            }
            var bound = args.Select(a => BindExpression(a, scope)).ToList();
            if (bound.Any(b => b is null)) return null;
            // log and sqrt of a multivector with more than a scalar part: of a rotor or motor.
            if (name is "log" or "sqrt" && bound[0]!.Type is { Frame: { } frame, GradeMask: not 1 } type)
                return BindVersorFunction(name, bound[0]!, frame, type, span);
            return CheckConstant(new BoundScalarFunctionCall(fn.Function, bound!, span), call.GetText);
        }
        if (scope.Macro is null)
        {
            if (UnaryOperators.ContainsKey(name) || OtherBuiltins.Contains(name) || _macros.ContainsKey(name))
                _diagnostics.ReportInvalidScalar(span, $"'{name}' works on multivectors and cannot appear in a constant scalar expression");
            else
                ReportUnknown(Span(call.qualifiedName()), "scalar function", name, ScalarFunctions.Keys.Append("exp"));
            return null;
        }
        return BindMacroScopeCall(call, name, args, scope, span);
    }
}
