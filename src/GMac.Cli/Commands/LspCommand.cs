using System.Text.Json;
using GMac.Cli.LanguageServer;
using StreamJsonRpc;

namespace GMac.Cli.Commands;

/// <summary>
/// <c>gmac lsp</c>: the GMacDSL language server, speaking the Language Server Protocol (JSON-RPC
/// with Content-Length headers) over standard input and output; its log goes to standard error.
/// </summary>
internal static class LspCommand
{
    public static System.CommandLine.Command Create()
    {
        var command = new System.CommandLine.Command("lsp", "Run the GMacDSL language server over standard input and output (for editors).");
        command.SetAction(r => Run(r.InvocationConfiguration.Error));
        return command;
    }

    private static int Run(TextWriter error)
    {
        var log = TextWriter.Synchronized(error);
        var formatter = new SystemTextJsonFormatter();
        formatter.JsonSerializerOptions.PropertyNamingPolicy = JsonNamingPolicy.CamelCase;
        formatter.JsonSerializerOptions.DefaultIgnoreCondition = System.Text.Json.Serialization.JsonIgnoreCondition.WhenWritingNull;
        var handler = new TolerantMessageHandler(Console.OpenStandardOutput(), Console.OpenStandardInput(), formatter, log);
        var server = new LanguageServer.LanguageServer(log);
        using var rpc = new JsonRpc(handler);
        rpc.AddLocalRpcTarget(server, new JsonRpcTargetOptions { DisposeOnDisconnect = false });
        server.Attach(rpc);
        rpc.StartListening();
        // The client's 'exit' or the end of standard input ends the server.
        Task.WaitAny(rpc.Completion, server.Exited.Task);
        if (rpc.Completion.IsFaulted) log.WriteLine($"gmac lsp: connection ended: {rpc.Completion.Exception?.GetBaseException().Message}");
        return server.ShutdownRequested ? ExitCodes.Success : ExitCodes.Diagnostics;
    }
}
