using System.Text.Json;
using StreamJsonRpc;
using StreamJsonRpc.Protocol;

namespace GMac.Cli.LanguageServer;

/// <summary>
/// Content-Length framing that survives a message whose body is not JSON: StreamJsonRpc ends the
/// connection on one, but the framing already told where it ends, so the server logs it and reads on.
/// </summary>
internal sealed class TolerantMessageHandler(Stream sending, Stream receiving, IJsonRpcMessageFormatter formatter, TextWriter log)
    : HeaderDelimitedMessageHandler(sending, receiving, formatter)
{
    protected override async ValueTask<JsonRpcMessage?> ReadCoreAsync(CancellationToken cancellationToken)
    {
        while (true)
        {
            try
            {
                return await base.ReadCoreAsync(cancellationToken);
            }
            catch (Exception e) when (e is JsonException or BadRpcHeaderException)
            {
                await log.WriteLineAsync($"gmac lsp: unreadable message skipped: {e.Message}");
            }
        }
    }
}
