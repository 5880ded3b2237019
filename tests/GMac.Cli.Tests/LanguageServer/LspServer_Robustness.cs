using System.Text.Json.Nodes;

namespace GMac.Cli.Tests.LanguageServer;

public sealed class LspServer_Robustness
{
    [Fact]
    public void A_request_before_initialize_gets_an_empty_answer()
    {
        using var workspace = new LspWorkspace(initialize: false);
        Assert.Null(workspace.Client.At("textDocument/hover", workspace.MacrosPath, 0, 15));
        workspace.Client.Initialize(workspace.Folder);
        Assert.NotNull(workspace.Client.At("textDocument/hover", workspace.MacrosPath, 0, 15));
    }

    [Fact]
    public void A_message_that_is_not_json_or_has_wrong_parameters_is_skipped()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        client.SendRaw("{not json");
        Assert.Throws<InvalidOperationException>(() => client.Request("textDocument/hover", new JsonObject { ["position"] = "nowhere" }));
        client.Notify("textDocument/didChange", new JsonObject { ["textDocument"] = 42 });
        Assert.NotNull(client.At("textDocument/hover", workspace.MacrosPath, 0, 15));
        Assert.Contains("unreadable message skipped", client.Log, StringComparison.Ordinal);
        Assert.Equal(0, client.Shutdown());
    }

    [Fact]
    public void Exit_without_shutdown_ends_the_server_with_exit_code_1()
    {
        using var workspace = new LspWorkspace();
        workspace.Client.Notify("exit", null);
        var deadline = DateTime.UtcNow.AddSeconds(20);
        while (!workspace.Client.HasExited && DateTime.UtcNow < deadline) Thread.Sleep(20);
        Assert.True(workspace.Client.HasExited);
    }
}
