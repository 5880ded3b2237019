using System.Runtime.InteropServices;

namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>
/// Columns whose first element starts a 64-byte cache line. A managed array of doubles is only
/// 8-byte aligned, so most 32- and 64-byte vector loads and stores of it straddle two cache lines;
/// measured on this suite, that cost Vector512 code about a sixth of its speed (and a memory-bound
/// kernel half). Users who batch should align their columns the same way (docs/batches.md).
/// </summary>
public static class AlignedColumns
{
    private const int Alignment = 64;

    // Misaligned attempts stay referenced so the pinned heap does not hand the same place back.
    private static readonly List<double[]> Discarded = [];

    public static double[][] Allocate(int count, int length) => Enumerable.Range(0, count).Select(_ => Allocate(length)).ToArray();

    /// <summary>
    /// A pinned array (the pinned heap never moves it) whose data is 64-byte aligned: arrays are
    /// allocated, with a small spacer between tries to shift the next one, until one is aligned.
    /// </summary>
    public static double[] Allocate(int length)
    {
        lock (Discarded)
        {
            for (var attempt = 0; attempt < 64; attempt++)
            {
                var column = GC.AllocateArray<double>(length, pinned: true);
                if (length == 0 || Address(column) % Alignment == 0) return column;
                Discarded.Add(column);
                Discarded.Add(GC.AllocateArray<double>(1 + attempt % 7, pinned: true));
            }
        }
        throw new InvalidOperationException($"could not place a column of {length} doubles on a {Alignment}-byte boundary");
    }

    /// <summary>The address of element 0; the array is pinned, so it stays valid.</summary>
    public static nuint Address(double[] column)
    {
        var handle = GCHandle.Alloc(column, GCHandleType.Pinned);
        try { return (nuint)handle.AddrOfPinnedObject(); }
        finally { handle.Free(); }
    }
}
