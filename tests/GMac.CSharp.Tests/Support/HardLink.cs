using System.Runtime.InteropServices;

namespace GMac.CSharp.Tests.Support;

/// <summary>Hard links, which .NET cannot make: the C library's <c>link</c> (Unix only).</summary>
internal static class HardLink
{
    public static void Create(string existing, string newName) =>
        Assert.True(Link(existing, newName) == 0, $"link failed: {Marshal.GetPInvokeErrorMessage(Marshal.GetLastPInvokeError())}");

    [DllImport("libc", EntryPoint = "link", SetLastError = true)]
    private static extern int Link([MarshalAs(UnmanagedType.LPUTF8Str)] string existing, [MarshalAs(UnmanagedType.LPUTF8Str)] string newName);
}
