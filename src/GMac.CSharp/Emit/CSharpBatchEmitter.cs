using System.Text;
using GMac.Core.CodeGeneration;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GMac.CSharp.Emit;

/// <summary>
/// Prints a block as a loop over a batch of items in structure-of-arrays layout (<c>//GMac.Batch("i")</c>):
/// every binding that mentions the index reads or writes one element of a span or array, <c>S[i]</c>,
/// or one element of a member of an object of spans, <c>P[i].x</c> meaning <c>P.x[i]</c>; the others are
/// the same for every item. In a vector type the loop runs a whole vector of items per step (loads,
/// the vector code, stores), then the items left over one by one with the scalar code of the
/// element type; in a scalar type it is the scalar loop alone. All spans must have one length,
/// checked before anything is read.
/// </summary>
internal static class CSharpBatchEmitter
{
    private const string Global = "global::System.";

    /// <summary>The loop's code, or why the bindings do not make a batch (for a diagnostic at the Batch line).</summary>
    public static (string? Code, string? Problem) Emit(CodeBlock block, string index, string macroName, CSharpEmitOptions options)
    {
        if (block.EvaluatedOnce.Count > 0)
            return (null, $"a batch cannot read '{block.EvaluatedOnce[0].Trim()}': it calls, assigns or increments, and would run once for the whole batch; read it into a local before the region");
        if (block.Statements.OfType<VerbatimStatement>().Any())
            return (null, $"macro '{macroName}' writes its outputs through an output block, which a batch cannot write item by item; bind its outputs to spans instead");
        if (options.DeclareOutputs)
            return (null, $"no output of '{macroName}' is bound: bind each output coefficient to an element of a span, e.g. //GMac.Bind(\"w.e1\", \"<wx[{index}]>\")");

        var readNames = block.Statements.SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf()).OfType<VariableExpr>()
            .Select(v => v.Name).ToHashSet(StringComparer.Ordinal);
        var inputs = new List<(string Name, string Text, string? Collection)>();
        foreach (var (name, text) in block.InputText)
        {
            if (!readNames.Contains(name)) continue;
            var (collection, problem) = Item(text, index);
            if (problem is not null) return (null, problem);
            inputs.Add((name, text, collection));
        }
        var outputs = new List<(string Key, string Collection)>();
        foreach (var key in block.Outputs.Select(o => o.Target).Distinct())
        {
            var target = block.OutputTargets[key];
            var (collection, problem) = Item(target, index);
            if (problem is not null) return (null, problem);
            if (collection is null)
                return (null, $"output '{key}' is written to '{target.Trim()}', the same place for every item; in a batch bind it to an element of a span, e.g. \"<{StemOf(target)}[{index}]>\"");
            outputs.Add((key, collection));
        }
        var written = outputs.Select(o => o.Collection).ToHashSet(StringComparer.Ordinal);
        var collections = inputs.Select(i => i.Collection).OfType<string>().Concat(outputs.Select(o => o.Collection)).Distinct(StringComparer.Ordinal).ToList();
        if (collections.Count == 0)
            return (null, $"no binding reads a span at the index '{index}', so the batch has no items; bind inputs as \"<ux[{index}]>\"");

        var taken = block.InputText.Values.Concat(block.OutputTargets.Values)
            .SelectMany(t => SyntaxFactory.ParseTokens(t)).Where(t => t.IsKind(SyntaxKind.IdentifierToken)).Select(t => t.ValueText)
            .Append(index).ToHashSet(StringComparer.Ordinal);
        bool IsTaken(string name) => taken.Contains(name) || options.IsNameTaken(name);
        string Fresh(string stem)
        {
            for (var k = 0; ; k++)
                if (!IsTaken($"{stem}{k}") && taken.Add($"{stem}{k}")) return $"{stem}{k}";
        }

        var vector = VectorType.Find(options.ScalarType);
        var element = vector?.Element ?? options.ScalarType;
        var (indent, nl) = (options.Indent, options.NewLine);
        var inner = indent + "    ";
        var code = new StringBuilder();
        void Line(string prefix, string text) => code.Append(prefix).Append(text).Append(nl);

        if (options.IncludeStatistics) Line(indent, "// GMac: " + block.Statistics());
        var count = Fresh("count");
        Line(indent, $"int {count} = {collections[0]}.Length;");
        if (collections.Count > 1)
        {
            var message = $"{macroName}: the spans of a batch must have one length, that of {collections[0]}: {string.Join(", ", collections.Skip(1))}";
            Line(indent, $"if ({string.Join(" || ", collections.Skip(1).Select(c => $"{c}.Length != {count}"))}) throw new {Global}ArgumentException({SymbolDisplay.FormatLiteral(message, quote: true)});");
        }

        var tailTexts = inputs.ToDictionary(i => i.Name, i => i.Collection is null ? i.Text : $"{i.Collection}[{index}]", StringComparer.Ordinal);
        var tailInputs = block.InputText.ToDictionary(x => x.Key, x => tailTexts.GetValueOrDefault(x.Key, x.Value), StringComparer.Ordinal);
        var tailTargets = block.OutputTargets.ToDictionary(x => x.Key, x => x.Value, StringComparer.Ordinal);
        foreach (var (key, collection) in outputs) tailTargets[key] = $"{collection}[{index}]";

        // Values that read no span (a rotor's sine and cosine from one angle) are the same for every
        // item: computed once, before the loops, in the element type, and broadcast where the vector loop reads them.
        var (common, loopStatements) = Common(block, inputs.Where(i => i.Collection is null).Select(i => i.Name).ToHashSet(StringComparer.Ordinal));
        var commonNames = common.ToDictionary(a => a.Target, _ => Fresh("common"), StringComparer.Ordinal);
        if (common.Count > 0)
        {
            var commonBlock = new CodeBlock(common.Select(a => a with { IsOutput = true }),
                tailInputs.Concat(commonNames).ToDictionary(StringComparer.Ordinal), commonNames);
            var (_, commonBody) = CSharpScalarEmitter.Instance.EmitParts(commonBlock, options with
            {
                ScalarType = element,
                IncludeStatistics = false,
                DeclareOutputs = true,
                MayOverwrite = (_, _) => false,
                IsNameTaken = IsTaken,
            });
            code.Append(commonBody);
        }
        var loopReads = loopStatements.SelectMany(s => s.Expressions).SelectMany(e => e.DescendantsAndSelf()).OfType<VariableExpr>()
            .Select(v => v.Name).ToHashSet(StringComparer.Ordinal);
        var tailBlock = new CodeBlock(loopStatements, tailInputs.Concat(commonNames).ToDictionary(StringComparer.Ordinal), tailTargets);

        if (vector is null)
        {
            Line(indent, $"for (int {index} = 0; {index} < {count}; {index}++)");
        }
        else
        {
            var references = collections.ToDictionary(c => c, c => Fresh("span"), StringComparer.Ordinal);
            foreach (var c in collections)
                Line(indent, $"ref {element} {references[c]} = ref {Global}Runtime.InteropServices.MemoryMarshal.GetReference(({Global}{(written.Contains(c) ? "Span" : "ReadOnlySpan")}<{element}>){c});");
            var family = vector.Family;
            var vectorInputs = new Dictionary<string, string>(StringComparer.Ordinal);
            var loads = new List<string>();
            var broadcasts = inputs.Where(i => i.Collection is null).Select(i => (i.Name, Text: i.Text.Trim()))
                .Concat(commonNames.Select(c => (Name: c.Key, Text: c.Value)));
            foreach (var (name, text) in broadcasts.Where(b => loopReads.Contains(b.Name)))
            {
                vectorInputs[name] = Fresh("all");
                Line(indent, $"var {vectorInputs[name]} = {family}.Create<{element}>({text});");
            }
            foreach (var (name, _, collection) in inputs.Where(i => i.Collection is not null && loopReads.Contains(i.Name)))
            {
                vectorInputs[name] = Fresh("item");
                loads.Add($"var {vectorInputs[name]} = {family}.LoadUnsafe(ref {references[collection!]}, (nuint){index});");
            }
            var vectorTargets = outputs.ToDictionary(o => o.Key, _ => Fresh("result"), StringComparer.Ordinal);
            var vectorBlock = new CodeBlock(loopStatements,
                block.InputText.Keys.Concat(commonNames.Keys).ToDictionary(x => x, x => vectorInputs.GetValueOrDefault(x, block.InputText.GetValueOrDefault(x, "")), StringComparer.Ordinal),
                block.OutputTargets.ToDictionary(x => x.Key, x => vectorTargets.GetValueOrDefault(x.Key, x.Value), StringComparer.Ordinal));
            var (top, body) = CSharpVectorEmitter.Instance.EmitParts(vectorBlock, options with
            {
                Indent = inner,
                IncludeStatistics = false,
                DeclareOutputs = true,
                // Every output goes to a local of its own: nothing an input reads is written before the stores.
                MayOverwrite = (_, _) => false,
                IsNameTaken = IsTaken,
            });
            foreach (var t in top)
            {
                Line(indent, t);
                foreach (var token in SyntaxFactory.ParseTokens(t).Where(x => x.IsKind(SyntaxKind.IdentifierToken))) taken.Add(token.ValueText);
            }
            Line(indent, $"int {index} = 0;");
            Line(indent, $"for (; {index} <= {count} - {vector.Name}.Count; {index} += {vector.Name}.Count)");
            Line(indent, "{");
            foreach (var load in loads) Line(inner, load);
            code.Append(body);
            foreach (var (key, collection) in outputs) Line(inner, $"{family}.StoreUnsafe({vectorTargets[key]}, ref {references[collection]}, (nuint){index});");
            Line(indent, "}");
            Line(indent, $"for (; {index} < {count}; {index}++)");
        }
        // The common values are locals of this code: no output of the tail can overwrite them.
        var mayOverwrite = options.MayOverwrite;
        var (tailTop, tailBody) = CSharpScalarEmitter.Instance.EmitParts(tailBlock, options with
        {
            ScalarType = element,
            Indent = inner,
            IncludeStatistics = false,
            IsNameTaken = IsTaken,
            MayOverwrite = mayOverwrite is null ? null : (output, input) => !commonNames.ContainsKey(input) && mayOverwrite(output, input),
        });
        Line(indent, "{");
        foreach (var t in tailTop) Line(inner, t);
        code.Append(tailBody);
        Line(indent, "}");
        return (code.ToString(), null);
    }

    /// <summary>
    /// The temporaries that read only <paramref name="invariant"/> inputs and other such temporaries
    /// (each assigned once), in order, and the statements left for the loop.
    /// </summary>
    private static (List<AssignmentStatement> Common, List<CodeStatement> Loop) Common(CodeBlock block, HashSet<string> invariant)
    {
        var assignments = block.Statements.OfType<AssignmentStatement>().GroupBy(a => a.Target, StringComparer.Ordinal).ToDictionary(g => g.Key, g => g.Count(), StringComparer.Ordinal);
        var common = new List<AssignmentStatement>();
        var names = new HashSet<string>(invariant, StringComparer.Ordinal);
        var loop = new List<CodeStatement>();
        foreach (var s in block.Statements)
        {
            if (s is AssignmentStatement { IsOutput: false } a && assignments[a.Target] == 1
                && a.Value.DescendantsAndSelf().OfType<VariableExpr>().All(v => names.Contains(v.Name)))
            {
                common.Add(a);
                names.Add(a.Target);
            }
            else loop.Add(s);
        }
        return (common, loop);
    }

    /// <summary>
    /// The span a binding's text reads one item of: <c>S</c> for <c>S[i]</c>, <c>P.x</c> for
    /// <c>P[i].x</c>; null for a text that does not mention the index; a problem for any other use of it.
    /// </summary>
    private static (string? Collection, string? Problem) Item(string text, string index)
    {
        var e = Strip(SyntaxFactory.ParseExpression(text.Trim()));
        var uses = e.DescendantNodesAndSelf().OfType<IdentifierNameSyntax>().Count(n => n.Identifier.ValueText == index
            && !(n.Parent is MemberAccessExpressionSyntax m && m.Name == n) && n.Parent is not NameColonSyntax);
        if (uses == 0) return (null, null);
        var path = new List<string>();
        var node = e;
        while (node is MemberAccessExpressionSyntax member && member.IsKind(SyntaxKind.SimpleMemberAccessExpression))
        {
            path.Insert(0, member.Name.ToString());
            node = member.Expression;
        }
        if (uses == 1 && node is ElementAccessExpressionSyntax { ArgumentList.Arguments: [{ NameColon: null } argument] } access
            && argument.RefKindKeyword.IsKind(SyntaxKind.None) && Strip(argument.Expression) is IdentifierNameSyntax id && id.Identifier.ValueText == index)
            return (string.Join(".", path.Prepend(access.Expression.ToString().Trim())), null);
        return (null, $"'{text.Trim()}' uses the batch index '{index}' other than as the whole index of a span of items: a batch reads and writes S[{index}] (or P[{index}].x for a member x of spans), one item of each span per index");
    }

    private static ExpressionSyntax Strip(ExpressionSyntax e)
    {
        while (e is ParenthesizedExpressionSyntax p) e = p.Expression;
        return e;
    }

    private static string StemOf(string target)
    {
        var identifiers = SyntaxFactory.ParseTokens(target).Where(t => t.IsKind(SyntaxKind.IdentifierToken)).ToList();
        return identifiers.Count > 0 ? identifiers[^1].ValueText + "s" : "w";
    }
}
