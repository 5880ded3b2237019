using System.Text.Json.Nodes;

namespace GMac.Cli.Tests.LanguageServer;

public sealed class LspServer_Diagnostics
{
    [Fact]
    public void Initialize_announces_the_capabilities()
    {
        using var workspace = new LspWorkspace(initialize: false);
        var capabilities = workspace.Client.Initialize(workspace.Folder)!["capabilities"]!;
        Assert.Equal(1, (int)capabilities["textDocumentSync"]!["change"]!);
        foreach (var provider in new[] { "hoverProvider", "definitionProvider", "referencesProvider", "documentSymbolProvider" })
            Assert.True((bool)capabilities[provider]!, provider);
        Assert.NotNull(capabilities["completionProvider"]);
        Assert.NotNull(capabilities["codeLensProvider"]);
        Assert.Equal(0, workspace.Client.Shutdown());
    }

    [Fact]
    public void A_broken_document_gets_its_diagnostic_and_the_fix_an_empty_list()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        var uri = LspClient.Uri(workspace.MacrosPath);
        client.Open(workspace.MacrosPath, LspWorkspace.Macros.Replace("u op v", "u op q", StringComparison.Ordinal));

        var diagnostic = Assert.Single(client.DiagnosticsOf(uri))!;
        Assert.Equal("GMAC0101", (string?)diagnostic["code"]);
        Assert.Equal(1, (int)diagnostic["severity"]!);
        Assert.Equal("unknown multivector 'q'; did you mean 'u'?", (string?)diagnostic["message"]);
        AssertRange(diagnostic["range"]!, 4, 18, 4, 19);

        client.Change(workspace.MacrosPath, 2, LspWorkspace.Macros);
        Assert.Empty(client.DiagnosticsOf(uri));
        Assert.Equal(0, client.Shutdown());
    }

    [Fact]
    public void A_change_in_one_file_reports_what_it_breaks_in_another()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        // The class renamed in frames.gmac: its uses in macros.gmac (not open) no longer resolve.
        client.Open(workspace.FramesPath, LspWorkspace.Frames.Replace("e3.Vector", "e3.Vec", StringComparison.Ordinal));
        var diagnostics = client.DiagnosticsOf(LspClient.Uri(workspace.MacrosPath));
        Assert.NotEmpty(diagnostics);
        var first = diagnostics[0]!;
        Assert.StartsWith("GMAC", (string?)first["code"], StringComparison.Ordinal);
        Assert.Equal(1, (int)first["range"]!["start"]!["line"]!);

        client.Change(workspace.FramesPath, 2, LspWorkspace.Frames);
        Assert.Empty(client.DiagnosticsOf(LspClient.Uri(workspace.MacrosPath)));
    }

    [Fact]
    public void After_quick_changes_the_newest_text_has_the_last_word()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        var uri = LspClient.Uri(workspace.MacrosPath);
        client.Open(workspace.MacrosPath, LspWorkspace.Macros.Replace("u op v", "u op q", StringComparison.Ordinal));
        client.Change(workspace.MacrosPath, 2, LspWorkspace.Macros.Replace("u op v", "u op z", StringComparison.Ordinal));
        client.Change(workspace.MacrosPath, 3, LspWorkspace.Macros);
        client.WaitFor("textDocument/publishDiagnostics", p => (string?)p["uri"] == uri && p["diagnostics"]!.AsArray().Count == 0);
        // No list of an older text comes after it.
        Assert.Throws<TimeoutException>(() => client.WaitFor("textDocument/publishDiagnostics", p => (string?)p["uri"] == uri, TimeSpan.FromSeconds(1)));
    }

    [Fact]
    public void The_workspace_leaves_out_build_output_and_hidden_folders()
    {
        using var workspace = new LspWorkspace(initialize: false);
        // Copies that would define everything twice.
        foreach (var folder in new[] { "bin/Debug/dsl", "obj", "node_modules/x", ".git" })
            File.Copy(workspace.FramesPath, Path.Combine(Directory.CreateDirectory(Path.Combine(workspace.Folder, folder)).FullName, "frames.gmac"));
        workspace.Client.Initialize(workspace.Folder);
        workspace.Client.Open(workspace.MacrosPath, LspWorkspace.Macros);
        Assert.Empty(workspace.Client.DiagnosticsOf(LspClient.Uri(workspace.MacrosPath)));
        var references = workspace.Client.At("textDocument/references", workspace.FramesPath, 6, 30,
            new JsonObject { ["context"] = new JsonObject { ["includeDeclaration"] = true } })!.AsArray();
        Assert.Equal(
            [LspClient.Uri(workspace.FramesPath), LspClient.Uri(workspace.MacrosPath)],
            references.Select(r => (string)r!["uri"]!).Distinct().Order(StringComparer.Ordinal));
        Assert.Equal(0, workspace.Client.Shutdown());
    }

    [Fact]
    public void An_unknown_method_answers_method_not_found()
    {
        using var workspace = new LspWorkspace();
        var error = Assert.Throws<InvalidOperationException>(() => workspace.Client.Request("gmac/nonsense", new JsonObject()));
        Assert.Contains("-32601", error.Message, StringComparison.Ordinal);
        Assert.Equal(0, workspace.Client.Shutdown());
    }

    internal static void AssertRange(JsonNode range, int startLine, int startCharacter, int endLine, int endCharacter)
    {
        Assert.Equal(
            (startLine, startCharacter, endLine, endCharacter),
            ((int)range["start"]!["line"]!, (int)range["start"]!["character"]!, (int)range["end"]!["line"]!, (int)range["end"]!["character"]!));
    }
}
