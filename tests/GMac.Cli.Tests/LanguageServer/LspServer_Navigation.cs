using System.Text.Json.Nodes;

namespace GMac.Cli.Tests.LanguageServer;

public sealed class LspServer_Navigation
{
    [Fact]
    public void Definition_of_a_class_lands_on_its_name_in_the_other_file()
    {
        using var workspace = new LspWorkspace();
        var location = Assert.Single(workspace.Client.At("textDocument/definition", workspace.MacrosPath, 1, 24)!.AsArray())!;
        Assert.Equal(LspClient.Uri(workspace.FramesPath), (string?)location["uri"]);
        LspServer_Diagnostics.AssertRange(location["range"]!, 6, 28, 6, 34);
    }

    [Fact]
    public void Definition_of_a_called_macro_and_of_a_frame()
    {
        using var workspace = new LspWorkspace();
        var macro = Assert.Single(workspace.Client.At("textDocument/definition", workspace.MacrosPath, 11, 13)!.AsArray())!;
        Assert.Equal(LspClient.Uri(workspace.MacrosPath), (string?)macro["uri"]);
        LspServer_Diagnostics.AssertRange(macro["range"]!, 0, 13, 0, 18);
        var frame = Assert.Single(workspace.Client.At("textDocument/definition", workspace.MacrosPath, 4, 25)!.AsArray())!;
        LspServer_Diagnostics.AssertRange(frame["range"]!, 0, 13, 0, 15);
    }

    [Fact]
    public void References_of_a_class_are_every_use_and_its_declaration()
    {
        using var workspace = new LspWorkspace();
        var references = workspace.Client.At("textDocument/references", workspace.FramesPath, 6, 30,
            new JsonObject { ["context"] = new JsonObject { ["includeDeclaration"] = true } })!.AsArray();
        var found = references.Select(r => ((string)r!["uri"]!).EndsWith("frames.gmac", StringComparison.Ordinal) + ":" + Range(r!["range"]!)).ToList();
        Assert.Equal(
            ["True:6:28-6:34", "False:1:21-1:27", "False:1:36-1:42", "False:2:22-2:28", "False:8:21-8:27", "False:9:22-9:28"],
            found);

        var withoutDeclaration = workspace.Client.At("textDocument/references", workspace.MacrosPath, 11, 13,
            new JsonObject { ["context"] = new JsonObject { ["includeDeclaration"] = false } })!.AsArray();
        Assert.Equal(["11:12-11:17"], withoutDeclaration.Select(r => Range(r!["range"]!)));
    }

    [Fact]
    public void Document_symbols_outline_the_define_blocks()
    {
        using var workspace = new LspWorkspace();
        var symbols = workspace.Client.Request("textDocument/documentSymbol", new JsonObject
        {
            ["textDocument"] = new JsonObject { ["uri"] = LspClient.Uri(workspace.FramesPath) },
        })!.AsArray();
        Assert.Equal(["e3", "e3.vectors", "e3.Vector", "e3.I"], symbols.Select(s => (string)s!["name"]!));
        LspServer_Diagnostics.AssertRange(symbols[0]!["range"]!, 0, 0, 3, 9);
        LspServer_Diagnostics.AssertRange(symbols[0]!["selectionRange"]!, 0, 13, 0, 15);
    }

    [Fact]
    public void Completion_offers_keywords_names_and_the_members_of_a_frame()
    {
        using var workspace = new LspWorkspace();
        var all = workspace.Client.At("textDocument/completion", workspace.MacrosPath, 11, 12)!.AsArray().Select(c => (string)c!["label"]!).ToList();
        Assert.Contains("define", all);
        Assert.Contains("Cross", all);
        Assert.Contains("e3", all);
        // After "e3." (line 4: "        w = (u op v) gp e3.I;").
        var members = workspace.Client.At("textDocument/completion", workspace.MacrosPath, 4, 27)!.AsArray().Select(c => (string)c!["label"]!).ToList();
        Assert.Contains("Vector", members);
        Assert.Contains("I", members);
        Assert.DoesNotContain("define", members);
    }

    private static string Range(JsonNode range) =>
        $"{(int)range["start"]!["line"]!}:{(int)range["start"]!["character"]!}-{(int)range["end"]!["line"]!}:{(int)range["end"]!["character"]!}";
}
