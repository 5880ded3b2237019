using RayTracer.Cli;

namespace RayTracer.Tests.Cli;

/// <summary>
/// Base of the command-line tests: a fresh temporary folder per test (removed afterwards) and a way to
/// run <c>raytracer</c> in process with its exit code and both output streams.
/// </summary>
public abstract class CommandLineTest : IDisposable
{
    protected CommandLineTest()
    {
        Dir = Path.Combine(Path.GetTempPath(), "raytracer-" + GetType().Name + "-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(Dir);
    }

    /// <summary>The test's own temporary folder.</summary>
    protected string Dir { get; }

    protected static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        var code = Application.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    public void Dispose()
    {
        Directory.Delete(Dir, true);
        GC.SuppressFinalize(this);
    }
}
