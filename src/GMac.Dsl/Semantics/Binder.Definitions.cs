using Antlr4.Runtime;
using GMac.Core.Algebra;
using GMac.Core.Numerics;
using GMac.Dsl.Diagnostics;
using static GMac.Dsl.Syntax.Generated.GMacDslParser;

namespace GMac.Dsl.Semantics;

internal sealed partial class Binder
{
    /// <summary>Blade masks are ints and algebras grow as 2^n.</summary>
    private const int MaxFrameDimension = 16;

    // ------------------------------------------------------------------ frames

    private void DeclareFrame(FrameDefinitionContext syntax)
    {
        var name = syntax.name().GetText();
        if (_frames.TryGetValue(name, out var existing))
        {
            _diagnostics.ReportDuplicate(Span(syntax.name()), "frame", name, existing.Declaration);
            return;
        }
        var basis = new List<string>();
        foreach (var b in syntax.basisList().name())
        {
            if (basis.Contains(b.GetText()))
                _diagnostics.ReportDuplicate(Span(b), "basis vector", b.GetText(), Span(syntax.basisList()));
            else basis.Add(b.GetText());
        }
        if (basis.Count > MaxFrameDimension)
        {
            _diagnostics.ReportInvalidDefinition(Span(syntax.basisList()), $"a frame may have at most {MaxFrameDimension} basis vectors");
            basis = basis.Take(MaxFrameDimension).ToList();
        }
        var frame = new FrameSymbol(name, Span(syntax.name()), basis);
        frame.InnerProductMatrix = RationalMatrix.Identity(basis.Count);
        _frames[name] = frame;
        _frameBodies[frame] = (syntax.frameBody(), _file);

        var all = new List<int>();
        for (var mask = 0; mask < 1 << basis.Count; mask++) all.Add(mask);
        frame.MultivectorClass = new MultivectorClassSymbol("Multivector", frame.Declaration, frame)
        {
            VariableBlades = all,
            IsImplicit = true,
        };
        frame.Members["Multivector"] = frame.MultivectorClass;
    }

    private void ResolveFrame(FrameSymbol frame)
    {
        if (_resolved.Contains(frame)) return;
        if (!_resolving.Add(frame))
        {
            _diagnostics.ReportDefinitionCycle(frame.Declaration, "frame", CyclePath(frame));
            return;
        }
        _resolvingPath.Add(frame);
        var saved = _file;
        var (body, file) = _frameBodies[frame];
        _file = file;
        BindFrameBody(frame, body);
        _resolving.Remove(frame);
        _resolvingPath.Remove(frame);
        _resolved.Add(frame);
        _file = saved;
    }

    /// <summary>Names and diagnostics for a frame body; the matrices come from <see cref="BasisChange"/>.</summary>
    private void BindFrameBody(FrameSymbol frame, FrameBodyContext body)
    {
        var n = frame.Dimension;
        switch (body)
        {
            case EuclideanFrameContext:
                frame.Kind = FrameKind.Euclidean;
                break;
            case SignatureFrameContext s:
                frame.Kind = FrameKind.Signature;
                if (BindSignature(s, frame) is { } metric) frame.InnerProductMatrix = metric;
                break;
            case NamedSignatureFrameContext s:
                frame.Kind = FrameKind.Signature;
                if (BindNamedSignature(s, frame) is { } named) frame.InnerProductMatrix = named;
                break;
            case IpmFrameContext ipm:
                frame.Kind = FrameKind.InnerProductMatrix;
                if (BindMatrix(ipm.matrix(), n, n) is not { } m) break;
                if (m.FirstAsymmetry() is var (row, column))
                    _diagnostics.ReportNonSymmetricIpm(Span(ipm.matrix()), row + 1, column + 1);
                else frame.InnerProductMatrix = m;
                break;
            case OrthogonalizeFrameContext o:
                frame.Kind = FrameKind.Orthogonalized;
                if (SourceFrame(o.name(), frame, o) is not { } orthogonalized) break;
                frame.Source = orthogonalized;
                (frame.BasisChangeMatrix, frame.InnerProductMatrix) = BasisChange.Orthogonalize(orthogonalized.InnerProductMatrix);
                break;
            case SubspaceFrameContext sub:
                frame.Kind = FrameKind.SubspaceOf;
                if (SourceFrame(sub.name(), frame, null) is not { } whole || BindSubspaceIndices(sub, frame, whole) is not { } indices) break;
                Derive(frame, whole, BasisChange.Selection(whole.Dimension, indices));
                break;
            case TransformedFrameContext t:
                frame.Kind = FrameKind.TransformedByBcm;
                if (SourceFrame(t.name(), frame, t) is not { } transformed || BindMatrix(t.matrix(), n, n) is not { } bcm) break;
                if (bcm.TryInverse(out _)) Derive(frame, transformed, bcm);
                else _diagnostics.ReportInvalidDefinition(Span(t.matrix()), "basis change matrix is singular");
                break;
        }
    }

    /// <summary>The resolved frame a derived frame is built on; with <paramref name="sameDimensionAt"/>, it must match in dimension.</summary>
    private FrameSymbol? SourceFrame(NameContext name, FrameSymbol frame, ParserRuleContext? sameDimensionAt)
    {
        if (LookupFrame(name) is not { } source) return null;
        ResolveFrame(source);
        return sameDimensionAt is null || SameDimension(sameDimensionAt, source, frame) ? source : null;
    }

    private static void Derive(FrameSymbol frame, FrameSymbol source, RationalMatrix basisChange)
    {
        frame.Source = source;
        frame.BasisChangeMatrix = basisChange;
        frame.InnerProductMatrix = BasisChange.DerivedMetric(source.InnerProductMatrix, basisChange);
    }

    private RationalMatrix? BindSignature(SignatureFrameContext s, FrameSymbol frame)
    {
        var n = frame.Dimension;
        var counts = s.expr().Select(e => EvaluateInteger(e, "a signature count")).ToList();
        if (counts.Any(c => c is null)) return null;
        var (p, q, r) = (counts[0]!.Value, counts[1]!.Value, counts.Count > 2 ? counts[2]!.Value : 0);
        if (p < 0 || q < 0 || r < 0 || p + q + r != n)
        {
            _diagnostics.ReportInvalidDefinition(Span(s), $"signature ({p}, {q}, {r}) must count the {n} basis vectors of frame '{frame.Name}'");
            return null;
        }
        var diagonal = Enumerable.Repeat(Rational.One, p).Concat(Enumerable.Repeat(Rational.MinusOne, q))
            .Concat(Enumerable.Repeat(Rational.Zero, r)).ToList();
        WarnIfZeroIndexedVectorIsPositive(s, frame, diagonal, (p, q, r));
        return RationalMatrix.Diagonal(diagonal);
    }

    /// <summary>
    /// The counts assign +1, then −1, then 0 in basis order, so `basis {e0, e1, e2, e3}` with (3, 0, 1)
    /// makes e3 null, not the e0 the name suggests.
    /// </summary>
    private void WarnIfZeroIndexedVectorIsPositive(SignatureFrameContext s, FrameSymbol frame, List<Rational> diagonal, (int P, int Q, int R) counts)
    {
        var names = frame.BasisNames;
        // e0 is the null vector of PGA and the odd one out of a spacetime ((3, 1): e0 negative);
        // (1, 3) with e0 first is the usual timelike e0 and stays quiet.
        var odd = counts.R > 0 || (counts.Q > 0 && counts.P > counts.Q);
        if (!odd || names.Count < 2 || !names[0].EndsWith('0') || diagonal[0].Sign <= 0) return;
        var others = names.Select((n, i) => (n, d: diagonal[i])).Where(x => x.d.Sign <= 0)
            .Select(x => $"{x.n} {(x.d.IsZero ? "null" : "negative")}").ToList();
        // The suggestion swaps the first vector with the last null or negative one.
        var swapped = diagonal.ToList();
        var last = swapped.FindLastIndex(d => d.Sign <= 0);
        (swapped[0], swapped[last]) = (swapped[last], swapped[0]);
        var named = string.Join(", ", names.Select((n, i) => $"{n}: {(swapped[i].Sign > 0 ? "+1" : swapped[i].Sign < 0 ? "-1" : "0")}"));
        _diagnostics.ReportSignatureOrder(Span(s),
            $"signature ({counts.P}, {counts.Q}, {counts.R}) counts +1, -1, 0 in basis order: it makes {names[0]} positive and {string.Join(", ", others)}; "
            + $"to choose by name write e.g. signature {{{named}}}");
    }

    /// <summary>signature {e0: 0, e1: +1, …}: every basis vector once, its square an exact rational.</summary>
    private RationalMatrix? BindNamedSignature(NamedSignatureFrameContext s, FrameSymbol frame)
    {
        var squares = new Rational?[frame.Dimension];
        var ok = true;
        foreach (var entry in s.signatureEntry())
        {
            var name = entry.name().GetText();
            var i = frame.IndexOfBasis(name);
            if (i < 0)
            {
                ReportUnknown(Span(entry.name()), $"basis vector of frame '{frame.Name}'", name, frame.BasisNames);
                ok = false;
                continue;
            }
            if (squares[i] is not null)
            {
                _diagnostics.ReportInvalidDefinition(Span(entry), $"signature gives basis vector '{name}' twice");
                ok = false;
                continue;
            }
            if (EvaluateRational(entry.expr(), "the square of a basis vector") is { } square) squares[i] = square;
            else ok = false;
        }
        var missing = frame.BasisNames.Where((_, i) => squares[i] is null && ok).ToList();
        if (missing.Count > 0)
        {
            _diagnostics.ReportInvalidDefinition(Span(s), $"signature does not give the square of {string.Join(", ", missing.Select(m => $"'{m}'"))}");
            return null;
        }
        return ok ? RationalMatrix.Diagonal(squares.Select(x => x!.Value).ToList()) : null;
    }

    /// <summary>The position in <paramref name="whole"/> of each basis vector of the subspace frame, or null after reporting unknown ones.</summary>
    private List<int>? BindSubspaceIndices(SubspaceFrameContext sub, FrameSymbol frame, FrameSymbol whole)
    {
        var indices = new List<int>();
        foreach (var b in frame.BasisNames)
        {
            var i = whole.IndexOfBasis(b);
            if (i < 0) ReportUnknown(Span(sub), $"basis vector of frame '{whole.Name}'", b, whole.BasisNames);
            indices.Add(i);
        }
        return indices.Any(i => i < 0) ? null : indices;
    }

    private string CyclePath(Symbol repeated) =>
        string.Join(" -> ", _resolvingPath.Skip(_resolvingPath.IndexOf(repeated)).Append(repeated).Select(s => s.Name));

    private bool SameDimension(ParserRuleContext at, FrameSymbol source, FrameSymbol frame)
    {
        if (source.Dimension == frame.Dimension) return true;
        _diagnostics.ReportInvalidDefinition(Span(at),
            $"frame '{frame.Name}' has {frame.Dimension} basis vectors but '{source.Name}' has {source.Dimension}");
        return false;
    }

    /// <summary>A matrix of exact rational constants of the expected size.</summary>
    private RationalMatrix? BindMatrix(MatrixContext matrix, int rows, int columns)
    {
        var rowSyntax = matrix.matrixRow();
        var width = rowSyntax.Max(r => r.expr().Length);
        if (rowSyntax.Length != rows || rowSyntax.Any(r => r.expr().Length != columns))
        {
            _diagnostics.ReportMatrixSize(Span(matrix), rowSyntax.Length, width, rows);
            return null;
        }
        var m = new Rational[rows, columns];
        var ok = true;
        for (var i = 0; i < rows; i++)
        for (var j = 0; j < columns; j++)
        {
            var value = EvaluateRational(rowSyntax[i].expr(j), "a matrix entry");
            if (value is null) ok = false;
            else m[i, j] = value.Value;
        }
        return ok ? new RationalMatrix(m) : null;
    }

    private Rational? EvaluateRational(ExprContext syntax, string what)
    {
        var bound = BindExpression(syntax, Scope.Constant);
        return bound is null ? null : Fold(bound, syntax, what);
    }

    private Rational? Fold(BoundExpression bound, ExprContext syntax, string what)
    {
        if (Folding.TryFold(bound) is { } value) return value;
        _diagnostics.ReportInvalidScalar(Span(syntax), $"{what} must be an exact rational constant");
        return null;
    }

    private int? EvaluateInteger(ExprContext syntax, string what)
    {
        var value = EvaluateRational(syntax, what);
        if (value is null) return null;
        if (value.Value.IsInteger && value.Value.Abs() <= 1000) return (int)value.Value.Numerator;
        _diagnostics.ReportInvalidScalar(Span(syntax), $"{what} must be a small integer");
        return null;
    }

    // ------------------------------------------------------------------ transforms

    private void DeclareTransform(TransformDefinitionContext syntax)
    {
        var names = syntax.name();
        var name = names[0].GetText();
        if (_transforms.TryGetValue(name, out var existing))
        {
            _diagnostics.ReportDuplicate(Span(names[0]), "transform", name, existing.Declaration);
            return;
        }
        var source = LookupFrame(names[1]);
        var destination = LookupFrame(names[2]);
        if (source is null || destination is null)
        {
            _brokenNames.Add(name);
            return;
        }
        var transform = new TransformSymbol(name, Span(names[0])) { Source = source, Destination = destination };
        _transforms[name] = transform;
        _transformBodies[transform] = (syntax, _file);
    }

    private void ResolveTransform(TransformSymbol transform)
    {
        if (_resolved.Contains(transform)) return;
        if (!_resolving.Add(transform))
        {
            _diagnostics.ReportDefinitionCycle(transform.Declaration, "transform", CyclePath(transform));
            return;
        }
        _resolvingPath.Add(transform);
        var saved = _file;
        var (syntax, file) = _transformBodies[transform];
        _file = file;
        var (src, dst) = (transform.Source, transform.Destination);
        switch (syntax.transformBody())
        {
            case IdentityTransformContext i:
                transform.Kind = TransformKind.Identity;
                if (CheckDimensions(i, transform, dst.Dimension, src.Dimension))
                    transform.VectorMatrix = RationalMatrix.Identity(src.Dimension);
                break;
            case AliasTransformContext a:
                transform.Kind = TransformKind.AliasOf;
                if (Based(a.name(), transform) is { } aliased && CheckFrames(a, transform, aliased.Source, aliased.Destination))
                    transform.VectorMatrix = aliased.VectorMatrix;
                break;
            case InverseTransformContext inv:
                transform.Kind = TransformKind.InverseOf;
                if (Based(inv.name(), transform) is { } x && CheckFrames(inv, transform, x.Destination, x.Source) && x.VectorMatrix is { } m)
                {
                    if (m.TryInverse(out var inverse)) transform.VectorMatrix = inverse;
                    else _diagnostics.ReportNotInvertible(Span(inv.name()), x.Name);
                }
                break;
            case TransposeTransformContext tr:
                transform.Kind = TransformKind.TransposeOf;
                if (Based(tr.name(), transform) is { } y && CheckFrames(tr, transform, y.Destination, y.Source) && y.VectorMatrix is { } my)
                    transform.VectorMatrix = my.Transpose();
                break;
            case InverseTransposeTransformContext it:
                transform.Kind = TransformKind.InverseTransposeOf;
                if (Based(it.name(), transform) is { } z && CheckFrames(it, transform, z.Source, z.Destination) && z.VectorMatrix is { } mz)
                {
                    if (mz.TryInverse(out var inverse)) transform.VectorMatrix = inverse.Transpose();
                    else _diagnostics.ReportNotInvertible(Span(it.name()), z.Name);
                }
                break;
            case BcmOutermorphismContext b:
            {
                transform.Kind = TransformKind.OutermorphismUsingBcm;
                if (LookupFrame(b.name()) is not { } f) break;
                ResolveFrame(f);
                if (f.BasisChangeMatrix is null || f.Source is null)
                {
                    _diagnostics.ReportInvalidDefinition(Span(b.name()), $"frame '{f.Name}' is not derived from another frame, so it has no BCM");
                    break;
                }
                // Column i: derived basis vector i written in the source frame.
                if (CheckDimensions(b, transform, f.Source.Dimension, f.Dimension))
                    transform.VectorMatrix = f.BasisChangeMatrix.Transpose();
                break;
            }
            case MatrixOutermorphismContext mo:
                transform.Kind = TransformKind.OutermorphismUsingMatrix;
                if (src.Dimension == dst.Dimension)
                    transform.VectorMatrix = BindMatrix(mo.matrix(), dst.Dimension, src.Dimension);
                else CheckDimensions(mo, transform, dst.Dimension, src.Dimension);
                break;
        }
        _resolving.Remove(transform);
        _resolvingPath.Remove(transform);
        _resolved.Add(transform);
        _file = saved;
    }

    private TransformSymbol? Based(NameContext name, TransformSymbol transform)
    {
        var text = name.GetText();
        if (!_transforms.TryGetValue(text, out var other))
        {
            ReportUnknown(Span(name), "transform", text, _transforms.Keys);
            return null;
        }
        other.IsReferenced = true;
        transform.BasedOn = other;
        ResolveTransform(other);
        return other;
    }

    private bool CheckFrames(ParserRuleContext at, TransformSymbol transform, FrameSymbol source, FrameSymbol destination)
    {
        if (transform.Source == source && transform.Destination == destination) return true;
        _diagnostics.ReportInvalidDefinition(Span(at),
            $"transform '{transform.Name}' must map '{source.Name}' -> '{destination.Name}'");
        return false;
    }

    private bool CheckDimensions(ParserRuleContext at, TransformSymbol transform, int rows, int columns)
    {
        if (transform.Destination.Dimension == rows && transform.Source.Dimension == columns && rows == columns) return true;
        _diagnostics.ReportInvalidDefinition(Span(at),
            $"transform '{transform.Name}' needs frames of equal dimension; '{transform.Source.Name}' has {transform.Source.Dimension}, '{transform.Destination.Name}' has {transform.Destination.Dimension}");
        return false;
    }

    // ------------------------------------------------------------------ subspaces, classes, constants

    private T? DeclareMember<T>(QualifiedNameContext qualified, string kind, Func<string, SourceSpan, FrameSymbol, T> create) where T : Symbol
    {
        var parts = qualified.name();
        if (parts.Length != 2)
        {
            _diagnostics.ReportTypeError(Span(qualified), $"a {kind} is named frame.name, found '{qualified.GetText()}'");
            return null;
        }
        if (LookupFrame(parts[0]) is not { } frame)
        {
            _brokenNames.Add(qualified.GetText());
            return null;
        }
        var name = parts[1].GetText();
        if (frame.Members.TryGetValue(name, out var existing))
        {
            _diagnostics.ReportDuplicate(Span(parts[1]), kind, $"{frame.Name}.{name}", existing.Declaration);
            return null;
        }
        var symbol = create(name, Span(parts[1]), frame);
        frame.Members[name] = symbol;
        return symbol;
    }

    private void BindSubspace(SubspaceDefinitionContext syntax, SubspaceSymbol subspace)
    {
        var frame = subspace.Frame;
        var blades = new List<int>();
        switch (syntax.subspaceBody())
        {
            case BladeSubspaceContext b:
                foreach (var blade in b.bladeName())
                    if (BindBlade(blade, frame) is { } r && !blades.Contains(r.Mask)) blades.Add(r.Mask);
                break;
            case SpanSubspaceContext s:
            {
                var span = 0;
                foreach (var v in s.name())
                {
                    var i = frame.IndexOfBasis(v.GetText());
                    if (i < 0) ReportUnknown(Span(v), $"basis vector of frame '{frame.Name}'", v.GetText(), frame.BasisNames);
                    else span |= 1 << i;
                }
                for (var mask = 0; mask < 1 << frame.Dimension; mask++)
                    if ((mask & ~span) == 0) blades.Add(mask);
                break;
            }
        }
        subspace.Blades = blades;
    }

    private void BindClass(ClassDefinitionContext syntax, MultivectorClassSymbol cls)
    {
        var frame = cls.Frame;
        var variables = new List<int>();
        var constants = new List<ClassConstant>();
        cls.IsNormalized = syntax.NORMALIZED() is not null;
        foreach (var item in syntax.classItem())
        {
            switch (item)
            {
                case NormalizedItemContext:
                    cls.IsNormalized = true;
                    break;
                case SubspaceItemContext s:
                    if (LookupMember<SubspaceSymbol>(s.qualifiedName(), "subspace", frame) is { } sub)
                    {
                        if (sub.Frame != frame) _diagnostics.ReportFrameMismatch(Span(s), frame.Name, sub.Frame.Name);
                        else variables.AddRange(sub.Blades.Where(b => !variables.Contains(b)));
                    }
                    break;
                case ConstantCoefficientItemContext c:
                    if (BindBlade(c.bladeName(), frame) is { } blade && BindClassConstant(c.expr()) is { } value)
                        constants.Add(new ClassConstant(blade.Mask, blade.Sign < 0 ? -value : value));
                    break;
            }
        }
        // A constant coefficient fixes its blade; it is no longer a variable.
        variables.RemoveAll(b => constants.Any(c => c.Blade == b));
        cls.VariableBlades = variables;
        cls.ConstantCoefficients = constants;
    }

    /// <summary>
    /// A class constant is folded here, once, so that every user of the class (symbolic inputs,
    /// the numeric reference) sees the same exact value and none meets an expression it cannot fold.
    /// </summary>
    private Rational? BindClassConstant(ExprContext syntax)
    {
        var value = BindExpression(syntax, Scope.Constant);
        if (value is null) return null;
        if (!value.Type.IsScalar)
        {
            _diagnostics.ReportInvalidScalar(Span(syntax), "a coefficient must be a scalar");
            return null;
        }
        return Fold(value, syntax, "a class constant");
    }

    private void BindConstant(ConstantDefinitionContext syntax, ConstantSymbol constant) =>
        constant.Coefficients = BindCoefficientList(syntax.coefficientList(), constant.Frame, Scope.Constant);

    private List<CoefficientValue> BindCoefficientList(CoefficientListContext list, FrameSymbol frame, Scope scope)
    {
        var result = new List<CoefficientValue>();
        foreach (var c in list.coefficient())
        {
            var blade = BindBlade(c.bladeName(), frame);
            var value = BindExpression(c.expr(), scope);
            if (blade is null || value is null) continue;
            if (!value.Type.IsScalar)
            {
                _diagnostics.ReportInvalidScalar(Span(c.expr()), "a coefficient must be a scalar");
                continue;
            }
            if (result.Any(r => r.Blade.Mask == blade.Value.Mask))
            {
                _diagnostics.ReportDuplicate(Span(c.bladeName()), "coefficient", c.bladeName().GetText(), Span(list));
                continue;
            }
            result.Add(new CoefficientValue(blade.Value, value));
        }
        return result;
    }

    // ------------------------------------------------------------------ class bindings

    private void BindClassBinding(BindingDefinitionContext syntax)
    {
        var names = syntax.name();
        var name = names[0].GetText();
        if (_bindings.TryGetValue(name, out var existing))
        {
            _diagnostics.ReportDuplicate(Span(names[0]), "class binding", name, existing.Declaration);
            return;
        }
        if (LookupFrame(names[1]) is not { } frame) return;
        var binding = new ClassBindingSymbol(name, Span(names[0])) { Frame = frame };
        _bindings[name] = binding;
        binding.Coefficients = BindCoefficientList(syntax.coefficientList(), frame, Scope.Binding);
        var minimums = new Dictionary<string, Rational>();
        var maximums = new Dictionary<string, Rational>();
        foreach (var list in syntax.limitList())
        {
            var target = list.MIN() is not null ? minimums : maximums;
            foreach (var limit in list.limit())
            {
                var member = limit.memberReference() is { } m
                    ? string.Join(".", m.name().Select(n => n.GetText()))
                    : limit.name().GetText();
                if (EvaluateRational(limit.expr(), "a limit") is { } value) target[member] = value;
            }
        }
        foreach (var (member, min) in minimums)
            if (maximums.TryGetValue(member, out var max) && min > max)
                _diagnostics.ReportEmptyLimits(binding.Declaration, name, member, min.ToString(), max.ToString());
        binding.Minimums = minimums;
        binding.Maximums = maximums;
    }

    // ------------------------------------------------------------------ whole-project checks

    private void ReportCallCycles()
    {
        var state = new Dictionary<MacroSymbol, int>(); // 1 = on the path, 2 = done
        var path = new List<MacroSymbol>();
        foreach (var macro in _macros.Values) Visit(macro);

        void Visit(MacroSymbol macro)
        {
            state[macro] = 1;
            path.Add(macro);
            foreach (var callee in macro.Callees)
            {
                state.TryGetValue(callee, out var s);
                if (s == 1)
                {
                    var cycle = path.Skip(path.IndexOf(callee)).Select(m => m.Name).Append(callee.Name);
                    _diagnostics.ReportCyclicCall(callee.Declaration, string.Join(" -> ", cycle));
                }
                else if (s == 0) Visit(callee);
            }
            path.RemoveAt(path.Count - 1);
            state[macro] = 2;
        }
    }

    private void ReportUnused()
    {
        foreach (var frame in _frames.Values)
        foreach (var member in frame.MemberSymbols)
        {
            if (member.IsReferenced) continue;
            if (member is SubspaceSymbol) _diagnostics.ReportUnused(member.Declaration, "subspace", $"{frame.Name}.{member.Name}");
            else if (member is ConstantSymbol) _diagnostics.ReportUnused(member.Declaration, "constant", $"{frame.Name}.{member.Name}");
        }
        foreach (var transform in _transforms.Values.Where(t => !t.IsReferenced))
            _diagnostics.ReportUnused(transform.Declaration, "transform", transform.Name);
    }
}
