using System.Diagnostics;
using System.Runtime.InteropServices;

namespace RayTracer.Timing;

/// <summary>
/// The CPU time of the calling thread where the system tells it (Linux: CLOCK_THREAD_CPUTIME_ID),
/// so that time spent waiting for a core on a busy machine is not counted as test time; elsewhere
/// the wall clock.
/// </summary>
public static partial class ThreadCpuClock
{
    private const int ThreadCpuTimeClock = 3;

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    [LibraryImport("libc", EntryPoint = "clock_gettime")]
    private static partial int ClockGetTime(int clock, out TimeSpec time);

    private static readonly bool UsesThreadTime = OperatingSystem.IsLinux() && Probe();

    /// <summary>Whether readings are thread CPU time (true) or wall time.</summary>
    public static bool IsThreadTime => UsesThreadTime;

    /// <summary>A reading in milliseconds; only differences of readings on one thread mean anything.</summary>
    public static double NowMilliseconds()
    {
        if (UsesThreadTime && ClockGetTime(ThreadCpuTimeClock, out var time) == 0)
            return time.Seconds * 1e3 + time.Nanoseconds * 1e-6;
        return Stopwatch.GetTimestamp() * 1e3 / Stopwatch.Frequency;
    }

    private static bool Probe()
    {
        try
        {
            return ClockGetTime(ThreadCpuTimeClock, out _) == 0;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return false;
        }
    }
}
