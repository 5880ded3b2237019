using GMac.CSharp.BindingPoints;

namespace GMac.CSharp.Tests.Support;

/// <summary>Runs the host's flows in-process and captures their output and errors (exit 0 or 1, as gmac's).</summary>
internal static partial class Tool
{
    /// <summary><paramref name="beforeWrite"/> runs just before each file is written (to edit it during the run).</summary>
    public static (int Exit, string Out, string Err) Generate(IReadOnlyList<string> paths, bool check = false, bool stats = false, GenerationContext? context = null,
        Action<string>? beforeWrite = null)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var ok = SourceGeneration.Run(context ?? SharedDsl.Context, paths, check, stats, output, error, beforeWrite: beforeWrite);
        return (ok ? 0 : 1, output.ToString(), error.ToString());
    }

    public static (int Exit, string Out, string Err) Verify(params string[] paths)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var ok = SourceVerification.Run(SharedDsl.Context, paths, seed: 1, output, error);
        return (ok ? 0 : 1, output.ToString(), error.ToString());
    }
}
