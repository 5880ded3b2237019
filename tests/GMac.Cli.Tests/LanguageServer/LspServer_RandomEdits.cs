using System.Text;

namespace GMac.Cli.Tests.LanguageServer;

public sealed class LspServer_RandomEdits
{
    private static readonly string[] Requests =
        ["textDocument/hover", "textDocument/definition", "textDocument/references", "textDocument/completion", "textDocument/documentSymbol", "textDocument/codeLens"];

    [Fact]
    public void A_thousand_random_edits_never_end_the_server()
    {
        using var workspace = new LspWorkspace();
        var client = workspace.Client;
        client.Open(workspace.MacrosPath, LspWorkspace.Macros);
        var random = new Random(28);
        const string Alphabet = "abcdefgh{}()[]<>;:.,^*/+-=~!@#\"'0123456789 \n\tdefine end macro gp op e3.I /* */ //";
        var text = LspWorkspace.Macros;
        for (var version = 2; version < 1002; version++)
        {
            switch (random.Next(4))
            {
                case 0:
                    text = text[..random.Next(text.Length + 1)];
                    break;
                case 1 when text.Length > 0:
                    var at = random.Next(text.Length);
                    text = text.Remove(at, random.Next(Math.Min(10, text.Length - at) + 1));
                    break;
                default:
                    var insert = new StringBuilder();
                    for (var i = random.Next(1, 12); i > 0; i--)
                        insert.Append(random.Next(10) == 0 ? (char)random.Next(1, 0x3000) : Alphabet[random.Next(Alphabet.Length)]);
                    text = text.Insert(random.Next(text.Length + 1), insert.ToString());
                    break;
            }
            // Back to the whole document now and then, so that edits also break a valid one.
            if (text.Length < 20 || random.Next(50) == 0) text = LspWorkspace.Macros;
            client.Change(workspace.MacrosPath, version, text);
            // Requests in between, each on whatever the text is then (a request analyses it at once).
            if (version % 10 == 0)
                Ask(client, Requests[random.Next(Requests.Length)], workspace.MacrosPath, random.Next(14), random.Next(40));
        }
        Assert.False(client.HasExited, client.Log);
        // Every text was analysed without an internal failure (a failure is logged, and would be a defect).
        Assert.DoesNotContain("failed", client.Log, StringComparison.Ordinal);

        client.Change(workspace.MacrosPath, 1002, LspWorkspace.Macros);
        var hover = (string)client.At("textDocument/hover", workspace.MacrosPath, 0, 15)!["contents"]!["value"]!;
        Assert.Contains("3 additions/subtractions, 6 multiplications", hover, StringComparison.Ordinal);
        // Lists of texts typed before may still be on their way; the last one is empty.
        client.WaitFor("textDocument/publishDiagnostics", p => (string?)p["uri"] == LspClient.Uri(workspace.MacrosPath) && p["diagnostics"]!.AsArray().Count == 0);
        Assert.Equal(0, client.Shutdown());
    }

    /// <summary>A request whose answer may be ContentModified (-32801), never another error.</summary>
    private static void Ask(LspClient client, string method, string path, int line, int character)
    {
        try
        {
            client.At(method, path, line, character);
        }
        catch (InvalidOperationException e) when (e.Message.Contains("-32801", StringComparison.Ordinal))
        {
        }
    }
}
