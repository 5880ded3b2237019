using System.Text;
using System.Text.RegularExpressions;
using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Emit;

/// <summary>
/// What every C# emitter shares: names of temporaries, outputs held back from their inputs, values
/// evaluated once, sine–cosine pairs and output blocks, one statement per assignment. How a value
/// is printed (plain arithmetic, vector arithmetic) is the subclass's <see cref="ValueWriter"/>.
/// </summary>
public abstract partial class CSharpBlockEmitter : ICodeEmitter
{
    /// <summary>Preferred prefixes of temporary names; numbered ones follow when all of these clash.</summary>
    private static readonly string[] TemporaryPrefixes = ["tmp", "t", "tmpA", "tmpB", "tmpC", "gmacTmp"];

    public abstract IReadOnlyList<string> ScalarTypes { get; }

    /// <summary>Prints the values of one block; made afresh for each block.</summary>
    protected abstract class ValueWriter
    {
        public abstract string Print(Expr e);

        /// <summary>The call that computes sine and cosine of <paramref name="argument"/> together, as a tuple.</summary>
        public abstract string SinCos(Expr argument);

        /// <summary>Statements the values printed since the last call need before the statement that uses them.</summary>
        public virtual IReadOnlyList<string> TakeStatementsBefore() => [];

        /// <summary>Statements at the top of the block, after everything has been printed.</summary>
        public virtual IReadOnlyList<string> Prelude() => [];
    }

    /// <param name="variableText">The C# text of an input or temporary of the block.</param>
    /// <param name="freshName">A new name, starting with the given stem, that nothing in or around the block uses.</param>
    protected abstract ValueWriter CreateWriter(CSharpEmitOptions options, Func<string, string> variableText, Func<string, string> freshName);

    public string Emit(CodeBlock block, CSharpEmitOptions options)
    {
        var (top, body) = EmitParts(block, options);
        var sb = new StringBuilder();
        foreach (var line in top) sb.Append(options.Indent).Append(line).Append(options.NewLine);
        return sb.Append(body).ToString();
    }

    /// <summary>
    /// The block's code in two parts: statements that hold no value of the inputs (the statistics
    /// comment, broadcast constants, values evaluated once), unindented, and the indented statements
    /// after them. A batch loop keeps the first part out of its loop.
    /// </summary>
    internal (IReadOnlyList<string> Top, string Body) EmitParts(CodeBlock block, CSharpEmitOptions options)
    {
        if (!ScalarTypes.Contains(options.ScalarType))
            throw new InvalidOperationException($"No C# code for scalar type '{options.ScalarType}'; expected {string.Join(" or ", ScalarTypes)}.");
        var temps = block.Temporaries.Select(t => t.Target).Distinct().ToList();
        // The block's own C# text (bound inputs and output targets) names things the temporaries must not hide.
        var bound = block.InputText.Values.Concat(block.OutputTargets.Values).Concat(block.EvaluatedOnce)
            .SelectMany(text => IdentifierLike().Matches(text).Select(m => m.Value.TrimStart('@')))
            .ToHashSet(StringComparer.Ordinal);
        bool IsFree(string name) => !bound.Contains(name) && !options.IsNameTaken(name);
        var mayOverwrite = options.MayOverwrite ?? SharesRootName(block);
        var held = HeldOutputs(block, mayOverwrite);
        // Either the outputs that may overwrite inputs still to be read are held to the end, or
        // those inputs are read into locals and every output is written once the inputs it may
        // overwrite have been read (OutputPlacement). The second is measured faster (the line
        // through two points 1.15 of hand with its stores all at the end, 0.97 so). Across a math call
        // locals are spilled (every vector register is caller-saved on the System V ABI): code
        // that calls takes the copies only where they are no more locals than the held outputs.
        var order = OutputPlacement.Order(block, mayOverwrite);
        var copied = CopiedInputs(block, order, mayOverwrite);
        var calls = block.Statements.SelectMany(st => st.Expressions).Any(e => e.DescendantsAndSelf().Any(n => n is CallExpr));
        if (held.Count > 0 && (!calls || copied.Count <= held.Count)) held.Clear();
        else if (held.Count > 0)
        {
            copied.Clear();
            order = [.. block.Statements];
        }
        var copyPoints = OutputPlacement.CopyPoints(block, order, copied, mayOverwrite);
        // A held output whose value is a temporary assigned once (or a literal) needs no holder of
        // its own: the temporary keeps the value, and the output is written from it (negated) at the end.
        var assignedOnce = block.Temporaries.GroupBy(t => t.Target, StringComparer.Ordinal).Where(g => g.Count() == 1)
            .Select(g => g.Key).ToHashSet(StringComparer.Ordinal);
        bool Kept(Expr e) => e is ConstantExpr || e is VariableExpr v && assignedOnce.Contains(v.Name);
        bool KeepsItsValue(AssignmentStatement o) => Kept(o.Value) || o.Value is NegateExpr n && Kept(n.Operand);
        var holders = held.Count(o => !KeepsItsValue(o));
        var once = block.EvaluatedOnce;
        var numbered = temps.Count + holders + once.Count + copied.Count;
        var prefix = CandidatePrefixes().First(p => Enumerable.Range(0, numbered).All(i => IsFree($"{p}{i}")));
        var tempName = temps.Select((t, i) => (t, i)).ToDictionary(x => x.t, x => $"{prefix}{x.i}", StringComparer.Ordinal);
        var onceNames = once.Select((_, k) => $"{prefix}{temps.Count + holders + k}").ToList();
        var copyName = copied.Select((input, k) => (input, k)).ToDictionary(x => x.input, x => $"{prefix}{temps.Count + holders + once.Count + x.k}", StringComparer.Ordinal);
        var deferred = new List<(string Target, string Value)>();
        var heldSoFar = 0;
        var issued = Enumerable.Range(0, numbered).Select(i => $"{prefix}{i}").ToHashSet(StringComparer.Ordinal);

        string FreshName(string stem)
        {
            for (var k = 0; ; k++)
                if (IsFree($"{prefix}{stem}{k}") && issued.Add($"{prefix}{stem}{k}")) return $"{prefix}{stem}{k}";
        }

        string InputText(string input)
        {
            input = input.Trim();
            for (var k = 0; k < once.Count; k++) input = input.Replace(CodeBlock.EvaluatedOnceMarker(k), onceNames[k], StringComparison.Ordinal);
            return IsSimple(input) ? input : $"({input})";
        }

        string VariableText(string name) =>
            tempName.TryGetValue(name, out var t) ? t
            : copyName.TryGetValue(name, out var c) ? c
            : block.InputText.TryGetValue(name, out var input) ? InputText(input)
            : throw new InvalidOperationException($"'{name}' is neither an input nor a temporary of the block.");

        var writer = CreateWriter(options, VariableText, FreshName);
        var declaredType = DeclaredType(options);
        string Value(Expr e) => writer.Print(options.FusedMultiplyAdd ? FusedMultiplyAdds.Contract(e) : e);

        // A value dropped into an output block's text stands among operators the emitter cannot see
        // ("2 * <w.e1>" with w.e1 = a - b must read 2 * (a - b)): only a name or a literal that is not
        // negative goes in bare (a variable's text is already parenthesized where it needs to be).
        string Operand(Expr e) => e is VariableExpr or ConstantExpr { Value: >= 0 } ? Value(e) : $"({Value(e)})";

        var body = new StringBuilder();
        var declared = new HashSet<string>(StringComparer.Ordinal);
        var sinCos = new SinCosPairs(block);
        var line = new StringBuilder();
        for (var index = 0; index < order.Count; index++)
        {
            var s = order[index];
            foreach (var input in copyPoints.GetValueOrDefault(index) ?? [])
                body.Append(options.Indent).Append(declaredType).Append(' ').Append(copyName[input]).Append(" = ").Append(InputText(block.InputText[input])).Append(';').Append(options.NewLine);
            if (sinCos.IsDropped(s))
                continue;
            line.Clear();
            switch (s)
            {
                case AssignmentStatement { IsOutput: true } o when held.Contains(o) && KeepsItsValue(o):
                    deferred.Add((block.OutputTargets[o.Target].Trim(), Value(o.Value)));
                    continue;
                case AssignmentStatement { IsOutput: true } o when held.Contains(o):
                    var holder = $"{prefix}{temps.Count + heldSoFar++}";
                    line.Append(declaredType).Append(' ').Append(holder).Append(" = ").Append(Value(o.Value)).Append(';');
                    deferred.Add((block.OutputTargets[o.Target].Trim(), holder));
                    break;
                case AssignmentStatement { IsOutput: true } o:
                    var target = block.OutputTargets[o.Target].Trim();
                    if (options.DeclareOutputs && declared.Add(target)) line.Append(declaredType).Append(' ');
                    line.Append(target).Append(" = ").Append(Value(o.Value)).Append(';');
                    break;
                case AssignmentStatement t when sinCos.TryGetPair(t, out var pair):
                    var (sine, cosine) = (tempName[pair.Sine], tempName[pair.Cosine]);
                    declared.Add(sine);
                    declared.Add(cosine);
                    line.Append("var (").Append(sine).Append(", ").Append(cosine).Append(") = ").Append(writer.SinCos(pair.Argument)).Append(';');
                    break;
                case AssignmentStatement t:
                    var name = tempName[t.Target];
                    if (declared.Add(name)) line.Append(declaredType).Append(' ');
                    line.Append(name).Append(" = ").Append(Value(t.Value)).Append(';');
                    break;
                case VerbatimStatement v:
                    // An output block's text has the line endings of its .gmac file: give it the file's own.
                    foreach (var part in v.Parts) line.Append(part.Text is { } text ? LineBreak().Replace(text, options.NewLine) : Operand(part.Value!));
                    break;
            }
            foreach (var before in writer.TakeStatementsBefore()) body.Append(options.Indent).Append(before).Append(options.NewLine);
            body.Append(options.Indent).Append(line).Append(options.NewLine);
        }
        foreach (var (target, holder) in deferred)
        {
            body.Append(options.Indent);
            if (options.DeclareOutputs && declared.Add(target)) body.Append(declaredType).Append(' ');
            body.Append(target).Append(" = ").Append(holder).Append(';').Append(options.NewLine);
        }

        var top = new List<string>();
        if (options.IncludeStatistics) top.Add("// GMac: " + block.Statistics());
        top.AddRange(writer.Prelude());
        // Expressions with effects (calls, increments) run once, in binding order, before anything is written.
        for (var k = 0; k < once.Count; k++) top.Add($"var {onceNames[k]} = {once[k].Trim()};");
        return (top, body.ToString());
    }

    /// <summary>How a local of the code is declared: its scalar type, or <c>var</c> where that type is the value's own.</summary>
    protected virtual string DeclaredType(CSharpEmitOptions options) => options.ScalarType;

    /// <summary>The <c>Math</c> function for a neutral name (<c>MathF</c>'s with <paramref name="single"/>, so no value is widened to double).</summary>
    protected static string ScalarFunction(string f, bool single)
    {
        var function = f switch
        {
            "sin" => "Math.Sin",
            "cos" => "Math.Cos",
            "tan" => "Math.Tan",
            "acos" => "Math.Acos",
            "sqrt" => "Math.Sqrt",
            "exp" => "Math.Exp",
            "log" => "Math.Log",
            "atan2" => "Math.Atan2",
            "abs" => "Math.Abs",
            "pow" => "Math.Pow",
            "sinh" => "Math.Sinh",
            "cosh" => "Math.Cosh",
            FusedMultiplyAdds.Function => "Math.FusedMultiplyAdd",
            _ => throw new InvalidOperationException($"No C# function for '{f}'."),
        };
        return single ? "MathF" + function["Math".Length..] : function;
    }

    /// <summary>A literal of the element type: shortest round-trip digits, <c>f</c>-suffixed for float.</summary>
    protected static string ScalarLiteral(ConstantExpr c, bool single) => single ? SingleLiteral.Of(c) : ExprPrinter.Literal(c.Value);

    /// <summary>An identifier, member access, element access or number: safe to use without parentheses.</summary>
    protected static bool IsSimple(string text) => SimpleExpression().IsMatch(text.Trim());

    /// <summary>
    /// Outputs whose target may be the storage of an input read after them: written in place, they
    /// would change that input under the statements still to read it (<c>a = a × b</c> bound to one
    /// variable). Their values are held in temporaries and written after the last statement.
    /// <paramref name="mayOverwrite"/> decides for an output and an input; without it, the names in
    /// their texts do.
    /// </summary>
    private static HashSet<AssignmentStatement> HeldOutputs(CodeBlock block, Func<string, string, bool> mayOverwrite)
    {
        var held = new HashSet<AssignmentStatement>(ReferenceEqualityComparer.Instance);
        var readLater = new HashSet<string>(StringComparer.Ordinal);
        for (var i = block.Statements.Count - 1; i >= 0; i--)
        {
            var s = block.Statements[i];
            if (s is AssignmentStatement { IsOutput: true } o && readLater.Any(input => mayOverwrite(o.Target, input)))
                held.Add(o);
            foreach (var e in s.Expressions)
            foreach (var v in e.DescendantsAndSelf().OfType<VariableExpr>())
                if (block.InputText.ContainsKey(v.Name))
                    readLater.Add(v.Name);
        }
        return held;
    }

    /// <summary>
    /// The inputs that some output may overwrite before a later statement of <paramref name="order"/>
    /// reads them, in the block's input order: read into locals, they let every output be written in place.
    /// </summary>
    private static List<string> CopiedInputs(CodeBlock block, IReadOnlyList<CodeStatement> order, Func<string, string, bool> mayOverwrite)
    {
        var copied = new HashSet<string>(StringComparer.Ordinal);
        var readLater = new HashSet<string>(StringComparer.Ordinal);
        for (var i = order.Count - 1; i >= 0; i--)
        {
            var s = order[i];
            if (s is AssignmentStatement { IsOutput: true } o)
                copied.UnionWith(readLater.Where(input => mayOverwrite(o.Target, input)));
            foreach (var e in s.Expressions)
            foreach (var v in e.DescendantsAndSelf().OfType<VariableExpr>())
                if (block.InputText.ContainsKey(v.Name))
                    readLater.Add(v.Name);
        }
        return block.InputText.Keys.Where(copied.Contains).ToList();
    }

    /// <summary>
    /// The fallback when no decision is given: whether the target's variable (its first name, after
    /// <c>this.</c>) is one the input's text reads. A textual approximation; gmac decides on the parsed syntax.
    /// </summary>
    private static Func<string, string, bool> SharesRootName(CodeBlock block) => (output, input) =>
    {
        var target = RootNames(block.OutputTargets[output]).FirstOrDefault();
        return target is null || RootNames(block.InputText[input]).Contains(target);
    };

    private static IEnumerable<string> RootNames(string text) =>
        RootName().Matches(ThisAccess().Replace(text, "")).Select(m => m.Value.TrimStart('@')).Where(n => n is not ("this" or "base"));

    /// <summary>A name that is not a member: not right after a dot or an arrow, and starting an identifier.</summary>
    [GeneratedRegex(@"(?<!(\.|->)\s*)(?<![\p{L}\p{N}_@])@?[\p{L}_][\p{L}\p{N}_]*")]
    private static partial Regex RootName();

    [GeneratedRegex(@"\b(this|base)\s*\.\s*")]
    private static partial Regex ThisAccess();

    /// <summary>
    /// The preferred prefixes, then <c>tmp_1_</c>, <c>tmp_2_</c>, …: each taken name rules out at most
    /// one of those, so a free one always comes within as many tries as there are taken names.
    /// </summary>
    private static IEnumerable<string> CandidatePrefixes()
    {
        foreach (var prefix in TemporaryPrefixes) yield return prefix;
        for (var k = 1; k < int.MaxValue; k++) yield return $"tmp_{k}_";
        throw new InvalidOperationException("No free name for temporaries.");
    }

    [GeneratedRegex(@"@?[A-Za-z_][A-Za-z0-9_]*")]
    private static partial Regex IdentifierLike();

    [GeneratedRegex(@"\r\n|\r|\n")]
    private static partial Regex LineBreak();

    [GeneratedRegex(@"^(@?[\p{L}_][\p{L}\p{N}_]*(\s*\.\s*@?[\p{L}_][\p{L}\p{N}_]*|\s*\[[^\[\]]*\])*|[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?[dD]?)$")]
    private static partial Regex SimpleExpression();
}
