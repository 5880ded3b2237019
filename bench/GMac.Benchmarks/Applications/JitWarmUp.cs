using System.Diagnostics;
using System.Runtime;

namespace GMac.Benchmarks.Applications;

/// <summary>
/// Runs code until the JIT has replaced its first code with its final code. Tiered compilation first
/// runs a loop as quickly compiled, unoptimized code and recompiles it only after the method has been
/// called for a while; in a process that has just compiled much else that can come seconds late. The
/// vector functions of .NET (Sin, SinCos, Exp…) and the scalar kernels' loops were measured up to ten
/// times slower before it; timed then, a kernel looks slower than the user's program will run it.
/// </summary>
public static class JitWarmUp
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(5);

    /// <summary>Runs in slices of <paramref name="slice"/> until a whole slice made the JIT compile nothing (at most 5 s).</summary>
    public static void Run(Action run, TimeSpan slice)
    {
        var total = Stopwatch.StartNew();
        long before;
        do
        {
            before = JitInfo.GetCompiledMethodCount();
            var watch = Stopwatch.StartNew();
            do run(); while (watch.Elapsed < slice);
        } while (JitInfo.GetCompiledMethodCount() != before && total.Elapsed < Limit);
    }
}
