using System.Diagnostics;

namespace GMac.CSharp.Tests.Support;

/// <summary>Named pipes for tests of tools that must not open them (opening one for reading waits for a writer).</summary>
internal static class Fifo
{
    public static void Create(string path)
    {
        using var process = Process.Start(new ProcessStartInfo("mkfifo", [path]) { UseShellExecute = false })!;
        process.WaitForExit();
        Assert.Equal(0, process.ExitCode);
    }

    /// <summary>Lets a reader blocked on the FIFO go on (it reads end of file), so a failing test does not leave a thread stuck.</summary>
    public static void Release(string path)
    {
        using var writer = new FileStream(path, FileMode.Open, FileAccess.Write);
    }
}
