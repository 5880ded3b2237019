using SafeFiles;

namespace GMac.CSharp.Tests.Support;

/// <summary>
/// A test of Unix file-system behaviour (permissions, owners, FIFOs, extended attributes): skipped
/// on Windows, when it needs root (or anyone but root) and runs otherwise, and when it needs
/// <c>user.*</c> extended attributes and the temporary folder's file system does not take them.
/// </summary>
internal sealed class UnixFactAttribute : FactAttribute
{
    public UnixFactAttribute(bool asRoot = false, bool asOtherUser = false, bool userAttributes = false)
    {
        if (OperatingSystem.IsWindows()) Skip = "needs a Unix file system";
        else if (asRoot && !Environment.IsPrivilegedProcess) Skip = "needs to run as root";
        else if (asOtherUser && Environment.IsPrivilegedProcess) Skip = "root may write any file";
        else if (userAttributes && WhyNoUserAttributes() is { } why) Skip = $"the file system of {Path.GetTempPath()} does not take user extended attributes: {why}";
    }

    private static string? WhyNoUserAttributes()
    {
        var probe = Path.GetTempFileName();
        try
        {
            return ExtendedAttributes.TrySet(probe, "user.gmac.probe", [1]);
        }
        finally
        {
            File.Delete(probe);
        }
    }
}
