using System.Runtime.InteropServices;

namespace GMac.Benchmarks.Generation;

/// <summary>
/// CPU time of the calling thread in milliseconds (Linux), which other processes on a loaded machine
/// do not inflate the way they inflate wall time; null where it is not available.
/// </summary>
internal static class ThreadCpuClock
{
    private const int ClockThreadCpuTimeId = 3;

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    [DllImport("libc", EntryPoint = "clock_gettime")]
    private static extern int ClockGetTime(int clock, out TimeSpec time);

    public static Func<double>? TryCreate()
    {
        if (!OperatingSystem.IsLinux()) return null;
        try
        {
            return ClockGetTime(ClockThreadCpuTimeId, out _) == 0 ? Now : null;
        }
        catch (DllNotFoundException)
        {
            return null;
        }
    }

    private static double Now()
    {
        ClockGetTime(ClockThreadCpuTimeId, out var t);
        return t.Seconds * 1000.0 + t.Nanoseconds / 1e6;
    }
}
