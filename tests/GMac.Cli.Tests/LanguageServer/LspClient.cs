using System.Collections.Concurrent;
using System.Diagnostics;
using System.Text;
using System.Text.Json.Nodes;
using GMac.Cli.Commands;

namespace GMac.Cli.Tests.LanguageServer;

/// <summary>
/// A client of <c>gmac lsp</c> as an editor is one: the built gmac.dll started with <c>dotnet</c>,
/// JSON-RPC messages with Content-Length headers over its standard input and output.
/// </summary>
internal sealed class LspClient : IDisposable
{
    private static readonly TimeSpan Wait = TimeSpan.FromSeconds(20);

    private readonly Process _process;
    private readonly Stream _input;
    private readonly ConcurrentDictionary<int, TaskCompletionSource<JsonNode?>> _pending = new();
    private readonly BlockingCollection<JsonObject> _notifications = [];
    private readonly StringBuilder _log = new();
    private readonly Lock _writing = new();
    private int _nextId;

    public LspClient()
    {
        var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        start.ArgumentList.Add(typeof(LspCommand).Assembly.Location);
        start.ArgumentList.Add("lsp");
        _process = Process.Start(start)!;
        _input = _process.StandardInput.BaseStream;
        _process.ErrorDataReceived += (_, e) => { lock (_log) _log.AppendLine(e.Data); };
        _process.BeginErrorReadLine();
        new Thread(ReadMessages) { IsBackground = true }.Start();
    }

    public bool HasExited => _process.HasExited;

    /// <summary>What the server wrote on standard error.</summary>
    public string Log { get { lock (_log) return _log.ToString(); } }

    public static string Uri(string path) => new Uri(path).AbsoluteUri;

    public JsonNode? Request(string method, JsonNode? parameters)
    {
        var id = Interlocked.Increment(ref _nextId);
        var answer = new TaskCompletionSource<JsonNode?>(TaskCreationOptions.RunContinuationsAsynchronously);
        _pending[id] = answer;
        Send(new JsonObject { ["jsonrpc"] = "2.0", ["id"] = id, ["method"] = method, ["params"] = parameters });
        if (Task.WhenAny(answer.Task, Task.Delay(Wait)).GetAwaiter().GetResult() != answer.Task) throw new TimeoutException($"no answer to {method} within {Wait}; server log:\n{Log}");
        return answer.Task.GetAwaiter().GetResult();
    }

    public void Notify(string method, JsonNode? parameters) =>
        Send(new JsonObject { ["jsonrpc"] = "2.0", ["method"] = method, ["params"] = parameters });

    /// <summary>The next notification for which <paramref name="match"/> holds (earlier ones are dropped).</summary>
    public JsonObject WaitFor(string method, Func<JsonObject, bool>? match = null, TimeSpan? wait = null)
    {
        var deadline = DateTime.UtcNow + (wait ?? Wait);
        while (DateTime.UtcNow < deadline)
        {
            if (_notifications.TryTake(out var message, TimeSpan.FromMilliseconds(100))
                && (string?)message["method"] == method && (match?.Invoke((JsonObject)message["params"]!) ?? true))
                return (JsonObject)message["params"]!;
        }
        throw new TimeoutException($"no {method} within {wait ?? Wait}; server log:\n{Log}");
    }

    /// <summary>The diagnostics published next for <paramref name="uri"/>.</summary>
    public JsonArray DiagnosticsOf(string uri) => (JsonArray)WaitFor("textDocument/publishDiagnostics", p => (string?)p["uri"] == uri)["diagnostics"]!;

    public JsonNode? Initialize(string workspace, bool standardLibrary = false)
    {
        var result = Request("initialize", new JsonObject
        {
            ["processId"] = null,
            ["rootUri"] = Uri(workspace),
            ["workspaceFolders"] = new JsonArray(new JsonObject { ["uri"] = Uri(workspace), ["name"] = "dsl" }),
            ["capabilities"] = new JsonObject(),
            ["initializationOptions"] = new JsonObject { ["dslFolders"] = new JsonArray(), ["standardLibrary"] = standardLibrary },
        });
        Notify("initialized", new JsonObject());
        return result;
    }

    public void Open(string path, string text) => Notify("textDocument/didOpen", new JsonObject
    {
        ["textDocument"] = new JsonObject { ["uri"] = Uri(path), ["languageId"] = "gmac", ["version"] = 1, ["text"] = text },
    });

    public void Change(string path, int version, string text) => Notify("textDocument/didChange", new JsonObject
    {
        ["textDocument"] = new JsonObject { ["uri"] = Uri(path), ["version"] = version },
        ["contentChanges"] = new JsonArray(new JsonObject { ["text"] = text }),
    });

    public JsonNode? At(string method, string path, int line, int character, JsonObject? extra = null)
    {
        var parameters = new JsonObject
        {
            ["textDocument"] = new JsonObject { ["uri"] = Uri(path) },
            ["position"] = new JsonObject { ["line"] = line, ["character"] = character },
        };
        foreach (var (name, value) in extra ?? []) parameters[name] = value?.DeepClone();
        return Request(method, parameters);
    }

    /// <summary>shutdown then exit, as a client ends a session; the server's exit code.</summary>
    public int Shutdown()
    {
        Request("shutdown", null);
        Notify("exit", null);
        if (!_process.WaitForExit(Wait)) throw new TimeoutException("the server did not exit");
        return _process.ExitCode;
    }

    private void Send(JsonObject message) => SendRaw(message.ToJsonString());

    /// <summary>A body as given, well-formed or not, in a correct frame.</summary>
    public void SendRaw(string text)
    {
        var body = Encoding.UTF8.GetBytes(text);
        lock (_writing)
        {
            _input.Write(Encoding.ASCII.GetBytes($"Content-Length: {body.Length}\r\n\r\n"));
            _input.Write(body);
            _input.Flush();
        }
    }

    private void ReadMessages()
    {
        var output = _process.StandardOutput.BaseStream;
        try
        {
            while (true)
            {
                var length = -1;
                string header;
                while ((header = ReadLine(output)) != "")
                {
                    if (header.StartsWith("Content-Length:", StringComparison.OrdinalIgnoreCase)) length = int.Parse(header["Content-Length:".Length..].Trim());
                }
                var body = new byte[length];
                output.ReadExactly(body);
                var message = JsonNode.Parse(body)!.AsObject();
                if (message["id"] is { } id && message["method"] is null && _pending.TryRemove((int)id, out var answer))
                {
                    if (message["error"] is { } error) answer.TrySetException(new InvalidOperationException(error.ToJsonString()));
                    else answer.TrySetResult(message["result"]);
                }
                else _notifications.Add(message);
            }
        }
        catch (EndOfStreamException)
        {
            // The server ended; waiting requests time out and say so.
        }
    }

    private static string ReadLine(Stream stream)
    {
        var line = new StringBuilder();
        while (true)
        {
            var b = stream.ReadByte();
            if (b < 0) throw new EndOfStreamException();
            if (b == '\n') return line.ToString().TrimEnd('\r');
            line.Append((char)b);
        }
    }

    public void Dispose()
    {
        if (!_process.HasExited) _process.Kill(entireProcessTree: true);
        _process.Dispose();
        _notifications.Dispose();
    }
}
