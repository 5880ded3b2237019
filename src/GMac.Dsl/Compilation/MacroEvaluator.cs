using System.Numerics;
using GMac.Core.Algebra;
using GMac.Dsl.Diagnostics;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// Runs the bound statements of a macro on <c>Multivector&lt;T&gt;</c>: with symbolic
/// scalars this is the macro compiler, with doubles the numeric reference.
/// <para>
/// <c>diff</c> uses <paramref name="differentiate"/> when given (the symbolic derivative);
/// otherwise it takes a central difference by re-running the macro's earlier
/// statements with the input coefficient moved by ±h.
/// </para>
/// </summary>
public sealed class MacroEvaluator<T>(CoreFrames frames, IScalarDomain<T> domain,
    Func<Multivector<T>, T, Multivector<T>?>? differentiate = null)
    where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
{
    private const double FiniteDifferenceStep = 1e-5;
    private const int MaxCallDepth = 64;

    /// <summary>A value of a statement: a multivector, or a plain scalar when <c>Multivector</c> is null.</summary>
    private readonly record struct Value(T Scalar, Multivector<T>? Multivector);

    private sealed record Context(MacroSymbol Macro, IReadOnlyDictionary<VariableSymbol, Multivector<T>> Inputs,
        Dictionary<VariableSymbol, Value> Environment, int StatementIndex, int Depth, RunState State);

    /// <summary>Per-run state: the observer and whether a <c>join on</c> region is open.</summary>
    private sealed class RunState(EvaluationObserver<T>? observer)
    {
        public EvaluationObserver<T>? Observer { get; } = observer;
        public bool Joined { get; set; }
    }

    // Per thread, so one evaluator can serve concurrent generations.
    private readonly ThreadLocal<EvaluationObserver<T>?> _observer = new();

    public CoreFrames Frames { get; } = frames;

    /// <summary>The outputs the macro assigns, from values for all its inputs.</summary>
    public IReadOnlyDictionary<VariableSymbol, Multivector<T>> Evaluate(MacroSymbol macro,
        IReadOnlyDictionary<VariableSymbol, Multivector<T>> inputs) => Evaluate(macro, inputs, 0);

    /// <summary>Evaluates with an observer (code generation).</summary>
    public IReadOnlyDictionary<VariableSymbol, Multivector<T>> Evaluate(MacroSymbol macro,
        IReadOnlyDictionary<VariableSymbol, Multivector<T>> inputs, EvaluationObserver<T>? observer)
    {
        var previous = _observer.Value;
        _observer.Value = observer;
        try
        {
            return Evaluate(macro, inputs, 0);
        }
        finally
        {
            _observer.Value = previous;
        }
    }

    /// <summary>A scalar expression outside any macro (class-binding coefficients), members read through the observer.</summary>
    public T EvaluateScalar(BoundExpression expression, EvaluationObserver<T> observer)
    {
        var macro = new MacroSymbol("<binding>", expression.Span);
        var context = new Context(macro, new Dictionary<VariableSymbol, Multivector<T>>(), new Dictionary<VariableSymbol, Value>(), 0, 0, new RunState(observer));
        return AsScalar(Evaluate(expression, context));
    }

    private Dictionary<VariableSymbol, Multivector<T>> Evaluate(MacroSymbol macro,
        IReadOnlyDictionary<VariableSymbol, Multivector<T>> inputs, int depth)
    {
        if (depth > MaxCallDepth)
            throw new MacroEvaluationException(macro.Declaration, $"macro calls nest deeper than {MaxCallDepth}");
        var env = Run(macro, inputs, macro.Statements.Count, depth);
        var outputs = new Dictionary<VariableSymbol, Multivector<T>>();
        foreach (var output in macro.Outputs)
            if (env.TryGetValue(output, out var value)) outputs[output] = AsMultivector(value, Frames[output.Frame!]);
        return outputs;
    }

    private Dictionary<VariableSymbol, Value> Run(MacroSymbol macro, IReadOnlyDictionary<VariableSymbol, Multivector<T>> inputs,
        int count, int depth)
    {
        var env = new Dictionary<VariableSymbol, Value>();
        var state = new RunState(_observer.Value);
        foreach (var input in macro.Inputs)
        {
            if (!inputs.TryGetValue(input, out var value))
                throw new MacroEvaluationException(input.Declaration, $"input '{input.Name}' of macro '{macro.Name}' has no value");
            env[input] = new Value(T.Zero, value);
        }
        for (var i = 0; i < count; i++)
        {
            // A statement that reaches no output is not evaluated: unused temporaries cost nothing.
            if (i < macro.LiveStatements.Length && !macro.LiveStatements[i]) continue;
            var context = new Context(macro, inputs, env, i, depth, state);
            try
            {
                Execute(macro.Statements[i], context);
            }
            catch (AlgebraException e)
            {
                throw AtSource(macro.Statements[i].Span, e);
            }
            catch (DivideByZeroException)
            {
                throw new MacroEvaluationException(macro.Statements[i].Span, DivisionByZeroMessage, DiagnosticCodes.GeneratedDivisionByZero);
            }
        }
        return env;
    }

    private void Execute(BoundStatement statement, Context context)
    {
        switch (statement)
        {
            case BoundAssignment a:
                var assigned = Evaluate(a.Value, context);
                context.Environment[a.Target] = context.State.Observer is { NameStatementsOnly: true } ? Named(assigned, a.Value, context) : assigned;
                break;
            case BoundCallStatement c:
            {
                var inputs = new Dictionary<VariableSymbol, Multivector<T>>();
                foreach (var b in c.Bindings.Where(b => b.Value is not null))
                    inputs[b.Parameter] = AsMultivector(Evaluate(b.Value!, context), Frames[b.Parameter.Frame!]);
                var outputs = Evaluate(c.Macro, inputs, context.Depth + 1);
                foreach (var b in c.Bindings.Where(b => b.Target is not null))
                    if (outputs.TryGetValue(b.Parameter, out var value)) context.Environment[b.Target!] = new Value(T.Zero, value);
                break;
            }
            case BoundJoinStatement j:
                context.State.Joined = j.IsOn;
                break;
            case BoundOutputStatement o when context.Depth == 0 && context.State.Observer?.OutputText is { } report:
                report(o, o.References.Select(r => AsScalar(Evaluate(r, context))).ToArray());
                break;
            // output text of called macros shapes nothing: only the generated macro's own text is emitted.
        }
    }

    private Multivector<T> AsMultivector(Value value, Frame frame) =>
        value.Multivector ?? Multivector<T>.FromScalar(frame, value.Scalar);

    private static T AsScalar(Value value) => value.Multivector is { } m ? m.ScalarPart : value.Scalar;

    private Multivector<T> Mv(BoundExpression e, Context context, Frame frame) => AsMultivector(Evaluate(e, context), frame);

    private T Scalar(BoundExpression e, Context context) => AsScalar(Evaluate(e, context));

    private Value Evaluate(BoundExpression expression, Context context)
    {
        var value = EvaluateUnnamed(expression, context);
        if (context.State.Observer is not { NameStatementsOnly: false }) return value;
        return Named(value, expression, context);
    }

    private static Value Named(Value value, BoundExpression expression, Context context)
    {
        if (context.State is { Joined: false, Observer.Name: { } name } && value.Multivector is { } mv
            && expression is not (BoundVariableReference or BoundNumber))
            value = value with { Multivector = name(mv) };
        return value;
    }

    private Value EvaluateUnnamed(BoundExpression expression, Context context)
    {
        var frame = expression.Type.Frame is { } f ? Frames[f] : null;
        switch (expression)
        {
            case BoundNumber n:
                return new Value(domain.FromRational(n.Value), null);
            case BoundVariableReference v:
                return context.Environment.TryGetValue(v.Variable, out var value)
                    ? value
                    : throw new MacroEvaluationException(v.Span, $"'{v.Variable.Name}' has no value here");
            case BoundConstantReference k:
                return new Value(T.Zero, Construct(Frames[k.Constant.Frame], k.Constant.Coefficients, context));
            case BoundMultivectorConstruction m:
                return new Value(T.Zero, Construct(Frames[m.Frame], m.Coefficients, context));
            case BoundMemberReference r:
                return context.State.Observer?.Member is { } member
                    ? new Value(member(r.Path), null)
                    : throw new MacroEvaluationException(r.Span, "member references have no value inside a macro");
            case BoundScalarFunctionCall call:
                return new Value(Apply(call, context), null);
            case BoundCoefficient c:
            {
                var operand = Evaluate(c.Operand, context);
                var coefficient = operand.Multivector is { } mv ? mv[new BasisBlade(c.Blade.Mask)] : c.Blade.Mask == 0 ? operand.Scalar : T.Zero;
                return new Value(c.Blade.Sign < 0 ? -coefficient : coefficient, null);
            }
            case BoundUnaryOperation u:
                return AtOperation(u, () => Unary(u, context, frame));
            case BoundBinaryOperation b:
                return AtOperation(b, () => Binary(b, context, frame));
            case BoundGradeProjection g:
                return new Value(T.Zero, Mv(g.Operand, context, frame!).Grade(g.Grade));
            case BoundVersorApplication a:
            {
                var (versor, operand) = (Mv(a.Versor, context, frame!), Mv(a.Operand, context, frame!));
                return AtOperation(a, () => new Value(T.Zero, versor.Apply(operand)));
            }
            case BoundTransformApplication t:
            {
                var source = Frames[t.Transform.Source];
                var map = Outermorphism<T>.FromMatrix(source, Frames[t.Transform.Destination],
                    t.Transform.VectorMatrix
                        ?? throw new MacroEvaluationException(t.Span, $"transform '{t.Transform.Name}' has no matrix"));
                return new Value(T.Zero, map.Apply(Mv(t.Operand, context, source)));
            }
            case BoundMacroCall call:
            {
                var inputs = new Dictionary<VariableSymbol, Multivector<T>>();
                for (var i = 0; i < call.Arguments.Count; i++)
                    inputs[call.Macro.Inputs[i]] = Mv(call.Arguments[i], context, Frames[call.Macro.Inputs[i].Frame!]);
                var outputs = Evaluate(call.Macro, inputs, context.Depth + 1);
                return outputs.TryGetValue(call.Macro.Outputs[0], out var result)
                    ? new Value(T.Zero, result)
                    : throw new MacroEvaluationException(call.Span, $"macro '{call.Macro.Name}' does not assign its output");
            }
            case BoundCast cast:
            {
                var operand = Mv(cast.Operand, context, frame!);
                var keep = cast.Blades.ToHashSet();
                var result = Multivector<T>.FromTerms(frame!, operand.Terms.Where(t => keep.Contains(t.Blade.Id)));
                return new Value(T.Zero, result);
            }
            case BoundDifferentiation d:
                return new Value(T.Zero, Differentiate(d, context, frame!));
            default:
                throw new MacroEvaluationException(expression.Span, $"cannot evaluate {expression.GetType().Name}");
        }
    }

    private Multivector<T> Construct(Frame frame, IReadOnlyList<CoefficientValue> coefficients, Context context) =>
        Multivector<T>.FromTerms(frame, coefficients.Select(c =>
        {
            var v = Scalar(c.Value, context);
            return (new BasisBlade(c.Blade.Mask), c.Blade.Sign < 0 ? -v : v);
        }));

    private T Apply(BoundScalarFunctionCall call, Context context)
    {
        var args = call.Arguments.Select(a => Scalar(a, context)).ToArray();
        return ScalarFunctions.TryApply(call.Function, args, domain, out var value)
            ? value
            : throw new MacroEvaluationException(call.Span, $"unknown function {call.Function}");
    }

    private Value Unary(BoundUnaryOperation u, Context context, Frame? frame)
    {
        if (u.Operator == UnaryOperator.Negate)
        {
            var v = Evaluate(u.Operand, context);
            return v.Multivector is { } m ? new Value(T.Zero, -m) : new Value(-v.Scalar, null);
        }
        var a = Mv(u.Operand, context, frame!);
        Multivector<T> Scalar(T s) => Multivector<T>.FromScalar(a.Frame, s);
        return new Value(T.Zero, u.Operator switch
        {
            UnaryOperator.Reverse => a.Reverse(),
            UnaryOperator.GradeInvolution => a.GradeInvolution(),
            UnaryOperator.CliffordConjugate => a.CliffordConjugate(),
            UnaryOperator.Inverse => a.Inverse(),
            UnaryOperator.GeneralInverse => a.GeneralInverse(context.State is { Joined: false, Observer.Name: { } name } ? name : null),
            UnaryOperator.Dual => a.Dual(),
            UnaryOperator.Undual => a.Undual(),
            UnaryOperator.RightComplement => a.RightComplement(),
            UnaryOperator.LeftComplement => a.LeftComplement(),
            UnaryOperator.Exp => InDomain(() => a.Exp(IsBladeByStructure(u.Operand, context.Macro, 0)), u),
            UnaryOperator.Log => InDomain(a.Log, u),
            UnaryOperator.VersorSqrt => InDomain(a.VersorSqrt, u),
            UnaryOperator.Norm => Scalar(a.Norm()),
            UnaryOperator.Norm2 => Scalar(a.Norm2()),
            // Quasi-norm: ⟨A Ã⟩₀ may be negative in a non-Euclidean metric, so no absolute value.
            UnaryOperator.QuasiNorm2 => Scalar(a.QuasiNorm()),
            UnaryOperator.QuasiNorm => Scalar(T.Sqrt(a.QuasiNorm())),
            _ => throw new MacroEvaluationException(u.Span, $"unknown operator {u.Operator}"),
        });
    }

    /// <summary>exp, log and sqrt refused for their operand (a 6D bivector, a boost's log) are blamed on the call.</summary>
    private static Multivector<T> InDomain(Func<Multivector<T>> f, BoundUnaryOperation u)
    {
        try
        {
            return f();
        }
        catch (AlgebraException e) when (!e.ExceedsLimit)
        {
            throw new MacroEvaluationException(u.Span, e.Message, DiagnosticCodes.OutsideDomain);
        }
    }

    /// <summary>
    /// Whether an expression is a blade however its coefficients are named: an outer product of
    /// vectors, scaled or negated, or a variable assigned once from such an expression.
    /// </summary>
    private static bool IsBladeByStructure(BoundExpression e, MacroSymbol macro, int depth) => depth < 16 && e switch
    {
        BoundBinaryOperation { Operator: BinaryOperator.Op } b => OuterProductChain(b) is not null,
        BoundBinaryOperation { Operator: BinaryOperator.Multiply } b when b.Left.Type.IsScalar || b.Left.Type.GradeMask == 1 =>
            IsBladeByStructure(b.Right, macro, depth + 1),
        BoundBinaryOperation { Operator: BinaryOperator.Multiply } b when b.Right.Type.IsScalar || b.Right.Type.GradeMask == 1 =>
            IsBladeByStructure(b.Left, macro, depth + 1),
        BoundBinaryOperation { Operator: BinaryOperator.Divide } b => IsBladeByStructure(b.Left, macro, depth + 1),
        BoundUnaryOperation { Operator: UnaryOperator.Negate } u => IsBladeByStructure(u.Operand, macro, depth + 1),
        BoundVariableReference { Variable.Kind: not VariableKind.Input } v =>
            macro.Statements.OfType<BoundAssignment>().Where(a => a.Target == v.Variable).ToList() is [var only]
            && IsBladeByStructure(only.Value, macro, depth + 1),
        _ => false,
    };

    /// <summary>
    /// An operation whose algebra fails (a null versor to invert, an exp it cannot take) is blamed on
    /// its own DSL expression, the innermost that fails, so the message can quote it as written.
    /// </summary>
    private static Value AtOperation(BoundExpression operation, Func<Value> evaluate)
    {
        try
        {
            return evaluate();
        }
        // A size limit stays with the whole statement, where restructuring is suggested.
        catch (AlgebraException e) when (!e.ExceedsLimit)
        {
            throw AtSource(operation.Span, e);
        }
    }

    private static MacroEvaluationException AtSource(SourceSpan span, AlgebraException e) =>
        new(span, e.Message, e.ExceedsLimit ? DiagnosticCodes.TooLarge : e.NotInvertible ? DiagnosticCodes.GeneratedNotInvertible : null, e);

    /// <summary>A division, blamed on its own DSL position when the divisor is (symbolically) zero.</summary>
    private static TResult Divide<TResult>(Func<TResult> divide, BoundBinaryOperation b)
    {
        try
        {
            return divide();
        }
        catch (DivideByZeroException)
        {
            throw new MacroEvaluationException(b.Span, DivisionByZeroMessage, DiagnosticCodes.GeneratedDivisionByZero);
        }
    }

    private const string DivisionByZeroMessage = "division by zero: the divisor simplifies to zero for these bindings";

    private Value Binary(BoundBinaryOperation b, Context context, Frame? frame)
    {
        if (frame is null)
        {
            var (x, y) = (Scalar(b.Left, context), Scalar(b.Right, context));
            return new Value(b.Operator switch
            {
                BinaryOperator.Add => x + y,
                BinaryOperator.Subtract => x - y,
                BinaryOperator.Divide => Divide(() => x / y, b),
                BinaryOperator.Power => domain.Pow(x, y),
                _ => x * y,
            }, null);
        }
        switch (b.Operator)
        {
            case BinaryOperator.Multiply:
            {
                // One side is scalar-valued; keep the other as the multivector.
                var leftScalar = b.Left.Type.IsScalar || b.Left.Type.GradeMask == 1;
                var (s, m) = leftScalar ? (b.Left, b.Right) : (b.Right, b.Left);
                return new Value(T.Zero, Mv(m, context, frame).Scale(Scalar(s, context)));
            }
            case BinaryOperator.Divide:
            {
                var (dividend, divisor) = (Mv(b.Left, context, frame), Scalar(b.Right, context));
                return new Value(T.Zero, Divide(() => dividend / divisor, b));
            }
        }
        if (b.Operator == BinaryOperator.Op && OuterProductChain(b) is { Count: >= 3 } factors)
        {
            var vectors = factors.Select(e => Mv(e, context, frame)).ToArray();
            var name = context.State is { Joined: false, Observer.Name: { } n } ? n : null;
            return new Value(T.Zero, Multivector<T>.OuterProductOfVectors(vectors, name));
        }
        var l = Mv(b.Left, context, frame);
        var r = Mv(b.Right, context, frame);
        return new Value(T.Zero, b.Operator switch
        {
            BinaryOperator.Add => l + r,
            BinaryOperator.Subtract => l - r,
            BinaryOperator.Gp => l.Gp(r),
            BinaryOperator.Op => l.Op(r),
            BinaryOperator.Sp => l.Sp(r),
            BinaryOperator.Lcp => l.Lcp(r),
            BinaryOperator.Rcp => l.Rcp(r),
            BinaryOperator.Fdp => l.Fdp(r),
            BinaryOperator.Hip => l.Hip(r),
            BinaryOperator.Cp => l.Cp(r),
            BinaryOperator.Acp => l.Acp(r),
            BinaryOperator.Vee => l.Regressive(r),
            _ => throw new MacroEvaluationException(b.Span, $"'{b.Operator}' needs scalar operands"),
        });
    }

    /// <summary>The factors of a ∧ b ∧ c ∧ … when every factor is a vector, else null.</summary>
    private static List<BoundExpression>? OuterProductChain(BoundBinaryOperation b)
    {
        var factors = new List<BoundExpression>();
        void Collect(BoundExpression e)
        {
            if (e is BoundBinaryOperation { Operator: BinaryOperator.Op } inner)
            {
                Collect(inner.Left);
                Collect(inner.Right);
            }
            else factors.Add(e);
        }
        Collect(b);
        return factors.All(f => f.Type.GradeMask == 1 << 1) ? factors : null;
    }

    private Multivector<T> Differentiate(BoundDifferentiation d, Context context, Frame frame)
    {
        var variable = (BoundVariableReference)d.Variable.Operand;
        var blade = new BasisBlade(d.Variable.Blade.Mask);
        if (differentiate is not null)
        {
            var coefficient = Mv(variable, context, Frames[variable.Variable.Frame!])[blade];
            return differentiate(Mv(d.Operand, context, frame), coefficient)
                ?? throw new MacroEvaluationException(d.Span, $"'{variable.Variable.Name}.<{frame.BladeName(blade)}>' is not a free variable here");
        }
        if (variable.Variable.Kind != VariableKind.Input || !context.Inputs.TryGetValue(variable.Variable, out var input))
            throw new MacroEvaluationException(d.Span, "numeric differentiation needs an input coefficient of the macro");
        var h = T.CreateChecked(FiniteDifferenceStep);
        Multivector<T> At(T delta)
        {
            var moved = new Dictionary<VariableSymbol, Multivector<T>>(context.Inputs)
            {
                [variable.Variable] = input + Multivector<T>.Basis(input.Frame, blade, delta),
            };
            var env = Run(context.Macro, moved, context.StatementIndex, context.Depth);
            return Mv(d.Operand, context with { Inputs = moved, Environment = env }, frame);
        }
        return (At(h) - At(-h)) / (h + h);
    }
}
