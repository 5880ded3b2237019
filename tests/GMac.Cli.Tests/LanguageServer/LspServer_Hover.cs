namespace GMac.Cli.Tests.LanguageServer;

public sealed class LspServer_Hover
{
    [Fact]
    public void A_macro_shows_its_signature_operation_counts_and_code()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        client.Open(workspace.MacrosPath, LspWorkspace.Macros);

        var hover = client.At("textDocument/hover", workspace.MacrosPath, 0, 15)!;
        var text = (string)hover["contents"]!["value"]!;
        Assert.Contains("macro Cross(inputs: { u : e3.Vector; v : e3.Vector }, outputs: { w : e3.Vector })", text, StringComparison.Ordinal);
        Assert.Contains("3 additions/subtractions, 6 multiplications, 0 divisions, 0 function calls", text, StringComparison.Ordinal);
        Assert.Contains("```csharp\nw_e1 = u_e3 * v_e2 - u_e2 * v_e3;", text, StringComparison.Ordinal);
        LspServer_Diagnostics.AssertRange(hover["range"]!, 0, 13, 0, 18);

        // The same at a call of the macro.
        var atCall = (string)client.At("textDocument/hover", workspace.MacrosPath, 11, 14)!["contents"]!["value"]!;
        Assert.Equal(text, atCall);
    }

    [Fact]
    public void A_class_a_constant_and_a_product_show_their_definitions()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        var vector = (string)client.At("textDocument/hover", workspace.MacrosPath, 1, 24)!["contents"]!["value"]!;
        Assert.Contains("define multivector class e3.Vector as vectors end multivector class", vector, StringComparison.Ordinal);
        var constant = (string)client.At("textDocument/hover", workspace.MacrosPath, 4, 27)!["contents"]!["value"]!;
        Assert.Contains("define constant e3.I as multivector { e1^e2^e3 : 1 } end constant", constant, StringComparison.Ordinal);
        var product = (string)client.At("textDocument/hover", workspace.MacrosPath, 4, 16)!["contents"]!["value"]!;
        Assert.StartsWith("outer product", product, StringComparison.Ordinal);
        Assert.Null(client.At("textDocument/hover", workspace.MacrosPath, 1, 14));
    }

    [Fact]
    public void The_code_lens_above_each_macro_counts_its_operations_and_follows_edits()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        client.Open(workspace.MacrosPath, LspWorkspace.Macros);
        var lens = client.Request("textDocument/codeLens", new System.Text.Json.Nodes.JsonObject
        {
            ["textDocument"] = new System.Text.Json.Nodes.JsonObject { ["uri"] = LspClient.Uri(workspace.MacrosPath) },
        })!.AsArray();
        Assert.Equal(2, lens.Count);
        Assert.Equal("3 adds, 6 muls, 0 divs", (string)lens[0]!["command"]!["title"]!);
        LspServer_Diagnostics.AssertRange(lens[0]!["range"]!, 0, 13, 0, 18);

        client.Change(workspace.MacrosPath, 2, LspWorkspace.Macros.Replace("(u op v) gp e3.I", "u gp v", StringComparison.Ordinal));
        lens = client.Request("textDocument/codeLens", new System.Text.Json.Nodes.JsonObject
        {
            ["textDocument"] = new System.Text.Json.Nodes.JsonObject { ["uri"] = LspClient.Uri(workspace.MacrosPath) },
        })!.AsArray();
        Assert.NotEqual("3 adds, 6 muls, 0 divs", (string)lens[0]!["command"]!["title"]!);
    }
}
