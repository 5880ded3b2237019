using System.Text;
using System.Text.Json;
using GMac.Cli.Commands;
using GMac.Dsl.Semantics;
using StreamJsonRpc;

namespace GMac.Cli.LanguageServer;

/// <summary>
/// The methods of <c>gmac lsp</c>. Each request catches its own failures (logged on standard
/// error, answered as an error or an empty result), so no document or request ends the server.
/// </summary>
internal sealed class LanguageServer(TextWriter log)
{
    private static readonly string[] Keywords =
    [
        "define", "end", "frame", "subspace", "multivector", "class", "constant", "binding", "macro", "transform", "as", "use",
        "basis", "signature", "Euclidean", "IPM", "BCM", "orthogonalize", "normalized", "inputs", "outputs", "performs", "output",
        "bind", "call", "join", "using", "alias", "identity", "inverse", "outermorphism", "transpose", "of", "by", "on", "off", "min", "max",
        "gp", "op", "sp", "lcp", "rcp", "fdp", "hip", "cp", "acp", "vee",
    ];

    private static readonly Dictionary<string, string> Products = new(StringComparer.Ordinal)
    {
        ["gp"] = "geometric product: `A gp B` = AB",
        ["op"] = "outer product: `A op B` = A∧B, the grade r+s part of AB for blades of grades r and s",
        ["sp"] = "scalar product: `A sp B` = A∗B = ⟨AB⟩₀",
        ["lcp"] = "left contraction: `A lcp B` = A⌋B = ⟨AB⟩ of grade s−r (zero when r > s)",
        ["rcp"] = "right contraction: `A rcp B` = A⌊B = ⟨AB⟩ of grade r−s (zero when s > r)",
        ["fdp"] = "fat-dot product: `A fdp B` = A•B = ⟨AB⟩ of grade |r−s|",
        ["hip"] = "Hestenes inner product: `A hip B` = ⟨AB⟩ of grade |r−s|, zero when A or B is a scalar",
        ["cp"] = "commutator product: `A cp B` = A×B = (AB − BA)/2",
        ["acp"] = "anti-commutator product: `A acp B` = (AB + BA)/2",
        ["vee"] = "regressive product: `A vee B` = lcomplement(rcomplement(A) ∧ rcomplement(B)), of grade r+s−n; metric independent (the meet in PGA)",
    };

    private Workspace? _workspace;
    private JsonRpc? _rpc;

    public bool ShutdownRequested { get; private set; }
    public TaskCompletionSource Exited { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

    public void Attach(JsonRpc rpc) => _rpc = rpc;

    [JsonRpcMethod("initialize", UseSingleObjectParameterDeserialization = true)]
    public object Initialize(InitializeParams parameters)
    {
        var options = parameters.InitializationOptions is { ValueKind: JsonValueKind.Object } o ? o : default;
        var folders = new List<string>();
        if (options.ValueKind == JsonValueKind.Object && options.TryGetProperty("dslFolders", out var dsl) && dsl.ValueKind == JsonValueKind.Array)
            folders.AddRange(dsl.EnumerateArray().Where(f => f.ValueKind == JsonValueKind.String).Select(f => Path.GetFullPath(f.GetString()!)));
        // No folders named: the workspace's (every .gmac file under them but build output and hidden folders).
        var wholeWorkspace = folders.Count == 0;
        if (wholeWorkspace)
        {
            folders.AddRange((parameters.WorkspaceFolders ?? []).Select(f => Uris.ToPath(f.Uri)));
            if (folders.Count == 0 && parameters.RootUri is { } root) folders.Add(Uris.ToPath(root));
            else if (folders.Count == 0 && parameters.RootPath is { } rootPath) folders.Add(Path.GetFullPath(rootPath));
        }
        if (options.ValueKind == JsonValueKind.Object && options.TryGetProperty("standardLibrary", out var library) && library.ValueKind == JsonValueKind.True)
            folders.Add(DslOptions.StandardLibraryDirectory);
        _workspace = new Workspace(folders, wholeWorkspace, p => _rpc!.NotifyWithParameterObjectAsync("textDocument/publishDiagnostics", p), log);
        log.WriteLine($"gmac lsp: DSL folders: {string.Join(", ", folders)}");
        return new
        {
            capabilities = new
            {
                textDocumentSync = new { openClose = true, change = 1 },
                hoverProvider = true,
                definitionProvider = true,
                referencesProvider = true,
                documentSymbolProvider = true,
                completionProvider = new { triggerCharacters = new[] { "." } },
                codeLensProvider = new { resolveProvider = false },
            },
            serverInfo = new { name = "gmac", version = typeof(LanguageServer).Assembly.GetName().Version?.ToString() },
        };
    }

    [JsonRpcMethod("initialized")]
    public static void Initialized()
    {
    }

    [JsonRpcMethod("shutdown")]
    public object? Shutdown()
    {
        ShutdownRequested = true;
        return null;
    }

    [JsonRpcMethod("exit")]
    public void Exit() => Exited.TrySetResult();

    [JsonRpcMethod("textDocument/didOpen", UseSingleObjectParameterDeserialization = true)]
    public void DidOpen(DidOpenTextDocumentParams parameters) => Guard("didOpen", () => Workspace.Open(Uris.ToPath(parameters.TextDocument.Uri), parameters.TextDocument.Text));

    [JsonRpcMethod("textDocument/didChange", UseSingleObjectParameterDeserialization = true)]
    public void DidChange(DidChangeTextDocumentParams parameters) => Guard("didChange", () =>
    {
        // Full synchronization: the last change holds the whole text.
        if (parameters.ContentChanges is [.., var last]) Workspace.Change(Uris.ToPath(parameters.TextDocument.Uri), last.Text);
    });

    [JsonRpcMethod("textDocument/didClose", UseSingleObjectParameterDeserialization = true)]
    public void DidClose(DidCloseTextDocumentParams parameters) => Guard("didClose", () => Workspace.Close(Uris.ToPath(parameters.TextDocument.Uri)));

    [JsonRpcMethod("workspace/didChangeWatchedFiles", UseSingleObjectParameterDeserialization = true)]
    public void DidChangeWatchedFiles(JsonElement parameters) => Guard("didChangeWatchedFiles", () => Workspace.FilesChanged());

    [JsonRpcMethod("textDocument/hover", UseSingleObjectParameterDeserialization = true)]
    public async Task<Hover?> HoverAsync(TextDocumentPositionParams parameters, CancellationToken cancellation)
    {
        try
        {
            var (analysis, text, token) = await At(parameters.TextDocument, parameters.Position, cancellation);
            if (text is null || token is not { } t) return null;
            var range = text.RangeOf(t.Start, t.Length);
            var word = text[t];
            if (Products.TryGetValue(word, out var product) && text.QualifierOf(t.Start) is null)
                return new Hover(new MarkupContent("markdown", product), range);
            return analysis.Resolve(text, t) switch
            {
                MacroSymbol macro when Workspace.IsCurrent(analysis) => new Hover(new MarkupContent("markdown", MacroHover(analysis, macro, cancellation)), range),
                MacroSymbol => throw ContentModified(),
                { } symbol => new Hover(new MarkupContent("markdown", $"```gmac\n{DefinitionText(analysis, symbol)}\n```"), range),
                null => null,
            };
        }
        catch (Exception e) when (e is not OperationCanceledException and not LocalRpcException and not OutOfMemoryException)
        {
            await log.WriteLineAsync($"gmac lsp: hover failed: {e}");
            return null;
        }
    }

    [JsonRpcMethod("textDocument/definition", UseSingleObjectParameterDeserialization = true)]
    public async Task<Location[]> DefinitionAsync(TextDocumentPositionParams parameters, CancellationToken cancellation)
    {
        try
        {
            var (analysis, text, token) = await At(parameters.TextDocument, parameters.Position, cancellation);
            if (text is null || token is not { } t || analysis.Resolve(text, t) is not { } symbol) return [];
            return analysis.NameLocation(symbol, Uris.FromPath) is { } location ? [location] : [];
        }
        catch (Exception e) when (e is not OperationCanceledException and not OutOfMemoryException)
        {
            await log.WriteLineAsync($"gmac lsp: definition failed: {e}");
            return [];
        }
    }

    [JsonRpcMethod("textDocument/references", UseSingleObjectParameterDeserialization = true)]
    public async Task<Location[]> ReferencesAsync(ReferenceParams parameters, CancellationToken cancellation)
    {
        try
        {
            var (analysis, text, token) = await At(parameters.TextDocument, parameters.Position, cancellation);
            if (text is null || token is not { } t || analysis.Resolve(text, t) is not { } symbol) return [];
            var declaration = analysis.NameLocation(symbol, Uris.FromPath);
            return [.. analysis.References(symbol)
                .Select(r => new Location(Uris.FromPath(r.Text.Path), r.Text.RangeOf(r.Token.Start, r.Token.Length)))
                .Where(l => parameters.Context?.IncludeDeclaration != false || l != declaration)
                .OrderBy(l => l.Uri, StringComparer.Ordinal).ThenBy(l => l.Range.Start.Line).ThenBy(l => l.Range.Start.Character)];
        }
        catch (Exception e) when (e is not OperationCanceledException and not OutOfMemoryException)
        {
            await log.WriteLineAsync($"gmac lsp: references failed: {e}");
            return [];
        }
    }

    [JsonRpcMethod("textDocument/documentSymbol", UseSingleObjectParameterDeserialization = true)]
    public async Task<DocumentSymbol[]> DocumentSymbolAsync(DocumentParams parameters, CancellationToken cancellation)
    {
        try
        {
            var analysis = await Workspace.CurrentAsync(cancellation);
            var path = Uris.ToPath(parameters.TextDocument.Uri);
            if (!analysis.Texts.TryGetValue(path, out var text)) return [];
            return [.. analysis.Definitions.Where(s => s.Declaration.FilePath == path)
                .Select(s => Outline(analysis, text, s)).OfType<DocumentSymbol>()
                .OrderBy(s => s.Range.Start.Line).ThenBy(s => s.Range.Start.Character)];
        }
        catch (Exception e) when (e is not OperationCanceledException and not OutOfMemoryException)
        {
            await log.WriteLineAsync($"gmac lsp: documentSymbol failed: {e}");
            return [];
        }
    }

    private static DocumentSymbol? Outline(Analysis analysis, SourceText text, Symbol symbol)
    {
        if (analysis.NameLocation(symbol, p => p) is not { } name) return null;
        var block = BlockOf(text, text.OffsetOf(name.Range.Start));
        var (kind, detail) = symbol switch
        {
            FrameSymbol f => (23, $"frame of {f.Dimension} basis vectors"),
            MultivectorClassSymbol c => (5, $"class {c.QualifiedName}"),
            ConstantSymbol k => (14, $"constant {k.QualifiedName}"),
            SubspaceSymbol s => (19, $"subspace {s.Frame.Name}.{s.Name}"),
            MacroSymbol m => (12, Signature(m)),
            ClassBindingSymbol => (11, "class binding"),
            _ => (21, "transform"),
        };
        var label = symbol switch
        {
            MultivectorClassSymbol c => c.QualifiedName,
            ConstantSymbol k => k.QualifiedName,
            SubspaceSymbol s => $"{s.Frame.Name}.{s.Name}",
            _ => symbol.Name,
        };
        var range = block is { } b ? text.RangeOf(b.Start, b.Length) : name.Range;
        return new DocumentSymbol(label, detail, kind, range, name.Range, null);
    }

    [JsonRpcMethod("textDocument/completion", UseSingleObjectParameterDeserialization = true)]
    public async Task<CompletionItem[]> CompletionAsync(TextDocumentPositionParams parameters, CancellationToken cancellation)
    {
        try
        {
            var analysis = await Workspace.CurrentAsync(cancellation);
            var path = Uris.ToPath(parameters.TextDocument.Uri);
            var model = analysis.Model;
            if (analysis.Texts.TryGetValue(path, out var text))
            {
                // After "frame." only the members of that frame.
                var offset = text.OffsetOf(parameters.Position);
                var start = offset;
                while (start > 0 && SourceText.IsIdentifierPart(text.Text[start - 1])) start--;
                if (text.QualifierOf(start) is { } q && model.Frames.TryGetValue(text[q], out var frame))
                {
                    return [.. frame.MemberSymbols.Where(m => m is not MultivectorClassSymbol { IsImplicit: true })
                        .Select(m => new CompletionItem(m.Name, m switch { MultivectorClassSymbol => 7, ConstantSymbol => 21, _ => 19 }, m.GetType().Name.Replace("Symbol", "", StringComparison.Ordinal)))
                        .Concat(frame.BasisNames.Select(b => new CompletionItem(b, 20, "basis vector")))
                        .Append(new CompletionItem("Multivector", 7, "the class of every multivector of the frame"))];
                }
            }
            return [.. Keywords.Select(k => new CompletionItem(k, 14, Products.TryGetValue(k, out var p) ? p : "keyword"))
                .Concat(model.Frames.Values.Select(f => new CompletionItem(f.Name, 9, "frame")))
                .Concat(model.Macros.Values.Select(m => new CompletionItem(m.Name, 3, Signature(m))))
                .Concat(model.ClassBindings.Values.Select(b => new CompletionItem(b.Name, 7, $"class binding of {b.Frame?.Name}")))
                .Concat(model.Transforms.Values.Select(t => new CompletionItem(t.Name, 3, "transform")))];
        }
        catch (Exception e) when (e is not OperationCanceledException and not OutOfMemoryException)
        {
            await log.WriteLineAsync($"gmac lsp: completion failed: {e}");
            return [];
        }
    }

    [JsonRpcMethod("textDocument/codeLens", UseSingleObjectParameterDeserialization = true)]
    public async Task<CodeLens[]> CodeLensAsync(DocumentParams parameters, CancellationToken cancellation)
    {
        try
        {
            var analysis = await Workspace.CurrentAsync(cancellation);
            var path = Uris.ToPath(parameters.TextDocument.Uri);
            var lenses = new List<CodeLens>();
            foreach (var macro in analysis.Model.Macros.Values.Where(m => m.Declaration.FilePath == path))
            {
                // Counts for a text already replaced are of no use: the client asks again.
                if (!Workspace.IsCurrent(analysis)) throw ContentModified();
                if (analysis.NameLocation(macro, p => p) is not { } name) continue;
                var code = await Task.Run(() => analysis.Generated(macro, cancellation), cancellation);
                var title = code?.Statistics is { } s ? Counts(s)
                    : code is null ? "not generated: the DSL has errors" : "not generated";
                lenses.Add(new CodeLens(name.Range, new LensCommand(title, "")));
            }
            return [.. lenses];
        }
        catch (Exception e) when (e is not OperationCanceledException and not LocalRpcException and not OutOfMemoryException)
        {
            await log.WriteLineAsync($"gmac lsp: codeLens failed: {e}");
            return [];
        }
    }

    /// <summary>LSP's ContentModified: the document changed while the answer was being made.</summary>
    private static LocalRpcException ContentModified() => new("the document changed") { ErrorCode = -32801 };

    private Workspace Workspace => _workspace ?? throw new InvalidOperationException("the server is not initialized");

    private void Guard(string method, Action action)
    {
        try
        {
            action();
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            log.WriteLine($"gmac lsp: {method} failed: {e}");
        }
    }

    private async Task<(Analysis Analysis, SourceText? Text, (int Start, int Length)? Token)> At(TextDocumentIdentifier document, Position position, CancellationToken cancellation)
    {
        var analysis = await Workspace.CurrentAsync(cancellation);
        if (!analysis.Texts.TryGetValue(Uris.ToPath(document.Uri), out var text)) return (analysis, null, null);
        return (analysis, text, text.IdentifierAt(text.OffsetOf(position)));
    }

    private static string Counts(GMac.Core.CodeGeneration.CodeStatistics s) =>
        $"{s.Additions} adds, {s.Multiplications} muls, {s.Divisions} divs" + (s.Calls > 0 ? $", {s.Calls} calls" : "");

    private static string Signature(MacroSymbol macro)
    {
        static string Parameters(IEnumerable<VariableSymbol> variables) =>
            string.Join("; ", variables.Select(v => $"{v.Name} : {v.Class?.QualifiedName ?? "?"}"));
        return $"macro {macro.Name}(inputs: {{ {Parameters(macro.Inputs)} }}, outputs: {{ {Parameters(macro.Outputs)} }})";
    }

    private static string MacroHover(Analysis analysis, MacroSymbol macro, CancellationToken cancellation)
    {
        var sb = new StringBuilder();
        sb.Append("```gmac\n").Append(Signature(macro)).Append("\n```\n\n");
        var code = analysis.Generated(macro, cancellation);
        if (code is null) return sb.Append("Not generated: the DSL has errors.").ToString();
        if (code.Statistics is not { } s) return sb.Append("Not generated: ").Append(code.Problem).ToString();
        sb.Append($"For default bindings: {s.Additions} additions/subtractions, {s.Multiplications} multiplications, {s.Divisions} divisions, {s.Calls} function calls ({s.Temporaries} temporaries)\n\n");
        return sb.Append("```csharp\n").Append(code.Code!.TrimEnd()).Append("\n```").ToString();
    }

    /// <summary>The text of the <c>define … end …</c> block that holds a definition, or its line.</summary>
    private static string DefinitionText(Analysis analysis, Symbol symbol)
    {
        if (!analysis.Texts.TryGetValue(symbol.Declaration.FilePath, out var text)) return symbol.Name;
        var at = text.OffsetOf(symbol.Declaration.Line, symbol.Declaration.Column);
        if (BlockOf(text, at) is { } block) return text.Text.Substring(block.Start, block.Length);
        return symbol.Name;
    }

    /// <summary>From the <c>define</c> before <paramref name="offset"/> to the end of the next <c>end KIND</c>.</summary>
    private static (int Start, int Length)? BlockOf(SourceText text, int offset)
    {
        var ids = text.Identifiers;
        var i = ids.Count - 1;
        while (i >= 0 && (ids[i].Start > offset || text[ids[i]] != "define")) i--;
        if (i < 0) return null;
        var start = ids[i].Start;
        for (var j = i + 1; j < ids.Count; j++)
        {
            if (text[ids[j]] == "define") return null;
            if (text[ids[j]] == "end" && j + 1 < ids.Count)
            {
                var kind = ids[j + 1];
                // "end multivector class" has two words.
                if (text[kind] == "multivector" && j + 2 < ids.Count) kind = ids[j + 2];
                return (start, kind.Start + kind.Length - start);
            }
        }
        return null;
    }
}
