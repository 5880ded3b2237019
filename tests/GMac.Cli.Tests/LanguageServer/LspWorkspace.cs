using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.LanguageServer;

/// <summary>A scratch workspace holding a small DSL in two files, and a server initialized on it.</summary>
internal sealed class LspWorkspace : IDisposable
{
    public const string Frames = """
        define frame e3 as
            basis: {e1, e2, e3}
            Euclidean
        end frame

        define subspace e3.vectors as basis {e1, e2, e3} end subspace
        define multivector class e3.Vector as vectors end multivector class
        define constant e3.I as multivector { e1^e2^e3 : 1 } end constant

        """;

    // Line 4 holds "u op v" (the v at column 18, 0-based); line 11 calls Cross.
    public const string Macros = """
        define macro Cross as
            inputs: { u : e3.Vector; v : e3.Vector }
            outputs: { w : e3.Vector }
            performs:
                w = (u op v) gp e3.I;
        end macro

        define macro Twice as
            inputs: { u : e3.Vector }
            outputs: { w : e3.Vector }
            performs:
                w = Cross(u, u) + 2 * u;
        end macro

        """;

    private readonly TempFolder _folder = new();

    public LspWorkspace(bool initialize = true)
    {
        FramesPath = _folder.Write("frames.gmac", Frames);
        MacrosPath = _folder.Write("macros.gmac", Macros);
        if (initialize) Client.Initialize(_folder.Path);
    }

    public LspClient Client { get; } = new();
    public string Folder => _folder.Path;
    public string FramesPath { get; }
    public string MacrosPath { get; }

    public void Dispose()
    {
        Client.Dispose();
        _folder.Dispose();
    }
}
