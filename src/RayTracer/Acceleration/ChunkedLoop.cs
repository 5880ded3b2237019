using System.Runtime.ExceptionServices;

namespace RayTracer.Acceleration;

/// <summary>
/// A loop over [0, count) in chunks run in parallel, or on the calling thread when there is only one
/// chunk: small scenes should not pay for waking the thread pool. The calling thread takes chunks too,
/// and pool threads take what is left when they start, so the loop never waits for a pool thread to wake
/// up (a few tens of microseconds or more, as long as a small mesh's whole loop), only for chunks already
/// under way. Bodies are best marked <c>[MethodImpl(MethodImplOptions.AggressiveOptimization)]</c>: a
/// build calls each only a few times, too few for tiered compilation to optimize it, and the first build
/// would run it unoptimized.
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

        var loop = new Loop(count, chunkSize, chunks, body);
        for (int i = Math.Min(Environment.ProcessorCount, chunks) - 1; i > 0; i--)
            ThreadPool.UnsafeQueueUserWorkItem(static l => l.Work(), loop, preferLocal: false);
        loop.Work();
        loop.Wait();
    }

    private sealed class Loop(int count, int chunkSize, int chunks, Action<int, int> body)
    {
        private int _next = -1;
        private int _finished;
        private ExceptionDispatchInfo? _failure;

        /// <summary>Runs chunks until none is left.</summary>
        public void Work()
        {
            int chunk;
            while ((chunk = Interlocked.Increment(ref _next)) < chunks)
            {
                try
                {
                    body(chunk * chunkSize, (int)Math.Min(count, (chunk + 1L) * chunkSize));
                }
                catch (Exception e)
                {
                    Interlocked.CompareExchange(ref _failure, ExceptionDispatchInfo.Capture(e), null); // rethrown by the calling thread
                }
                finally
                {
                    Interlocked.Increment(ref _finished);
                }
            }
        }

        /// <summary>Returns once every chunk is done, throwing the first failure, if any, on the calling thread.</summary>
        public void Wait()
        {
            var spin = new SpinWait();
            while (Volatile.Read(ref _finished) < chunks)
                spin.SpinOnce(sleep1Threshold: -1);
            _failure?.Throw();
        }
    }
}
