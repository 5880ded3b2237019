namespace RayTracer.Tracing;

/// <summary>
/// A named count of calls (rays cast, intersection tests run) cheap enough to leave on while
/// rendering: each thread bumps its own slot without locks or atomics, and <see cref="Total"/> sums
/// the slots of every thread that ever counted. Read totals when the render has finished.
/// </summary>
public sealed class InvocationCounter
{
    private static readonly object Gate = new();
    private static readonly List<long[]> AllSlots = [];
    private static readonly List<InvocationCounter> Registered = [];

    [ThreadStatic]
    private static long[]? _slots;

    private readonly int _index;

    public InvocationCounter(string name)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(name);
        Name = name;
        lock (Gate)
        {
            _index = Registered.Count;
            Registered.Add(this);
        }
    }

    public string Name { get; }

    /// <summary>Every counter created so far, in creation order.</summary>
    public static IReadOnlyList<InvocationCounter> All
    {
        get
        {
            lock (Gate)
                return [.. Registered];
        }
    }

    public void Increment()
    {
        var slots = _slots;
        if (slots is null || slots.Length <= _index)
            slots = Grow(_index);
        slots[_index]++;
    }

    /// <summary>Sum over all threads. Exact once the counting threads have finished.</summary>
    public long Total
    {
        get
        {
            lock (Gate)
            {
                var sum = 0L;
                foreach (var slots in AllSlots)
                    if (_index < slots.Length)
                        sum += Volatile.Read(ref slots[_index]);
                return sum;
            }
        }
    }

    /// <summary>Sets this counter to zero on every thread; call between experiments, not during one.</summary>
    public void Reset()
    {
        lock (Gate)
            foreach (var slots in AllSlots)
                if (_index < slots.Length)
                    Volatile.Write(ref slots[_index], 0);
    }

    private static long[] Grow(int index)
    {
        lock (Gate)
        {
            var old = _slots;
            var grown = new long[Math.Max(index + 1, Registered.Count)];
            if (old is not null)
            {
                old.CopyTo(grown, 0);
                // The old array's counts now live in the new one; keep only one of them summed.
                AllSlots.Remove(old);
            }
            AllSlots.Add(grown);
            _slots = grown;
            return grown;
        }
    }
}
