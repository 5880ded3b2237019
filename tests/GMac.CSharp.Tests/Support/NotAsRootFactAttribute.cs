namespace GMac.CSharp.Tests.Support;

/// <summary>A test that the system refuses to write a read-only file: skipped as root on Unix, whom it never refuses.</summary>
internal sealed class NotAsRootFactAttribute : FactAttribute
{
    public NotAsRootFactAttribute()
    {
        if (!OperatingSystem.IsWindows() && Environment.IsPrivilegedProcess) Skip = "root may write any file";
    }
}
