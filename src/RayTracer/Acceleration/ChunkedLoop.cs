namespace RayTracer.Acceleration;

/// <summary>
/// A loop over [0, count) in chunks run in parallel, or on the calling thread when there is only one
/// chunk: small scenes should not pay for waking the thread pool. Bodies are best marked
/// <c>[MethodImpl(MethodImplOptions.AggressiveOptimization)]</c>: a build calls each only a few times,
/// too few for tiered compilation to optimize it, and the first build would run it unoptimized.
/// </summary>
internal static class ChunkedLoop
{
    public static void For(int count, int chunkSize, Action<int, int> body)
    {
        int chunks = (int)(((long)count + chunkSize - 1) / chunkSize);
        if (chunks <= 1)
        {
            body(0, count);
            return;
        }

        Parallel.For(0, chunks, chunk => body(chunk * chunkSize, (int)Math.Min(count, (chunk + 1L) * chunkSize)));
    }
}
