namespace GMac.Cli.Tests.Support;

/// <summary>
/// A test of Unix file-system behaviour (permissions, owners, FIFOs): skipped on Windows, and when
/// it needs root (or anyone but root) and runs otherwise.
/// </summary>
internal sealed class UnixFactAttribute : FactAttribute
{
    public UnixFactAttribute(bool asRoot = false, bool asOtherUser = false)
    {
        if (OperatingSystem.IsWindows()) Skip = "needs a Unix file system";
        else if (asRoot && !Environment.IsPrivilegedProcess) Skip = "needs to run as root";
        else if (asOtherUser && Environment.IsPrivilegedProcess) Skip = "root may write any file";
    }
}
