using System.Runtime.InteropServices;

namespace GMac.Core.Symbolic;

/// <summary>
/// The hash-consing table behind <see cref="Atom"/>, <see cref="Monomial"/> and <see cref="Scalar"/>:
/// returns the one live object structurally equal to a candidate, or adopts the candidate. Objects
/// are held through weak GC handles, so partial results nobody references any more (the many
/// intermediate sums of a product) are collected instead of accumulating for the whole run.
/// Dead entries are swept whenever the table has doubled since the last sweep. Thread-safe.
/// </summary>
internal sealed class WeakInternTable<T>(IEqualityComparer<T> comparer) where T : class
{
    private const int MinimumSweepThreshold = 1 << 12;

    private readonly Lock _lock = new();
    // index + 1 of the first entry in the chain, 0 for none; the length is always a power of two,
    // so a bucket is the hash's low bits (the same as the remainder, without a division per look-up)
    private int[] _buckets = new int[1 << 10];
    private Entry[] _entries = new Entry[1 << 10];
    private int _count;
    private int _sweepThreshold = MinimumSweepThreshold;

    private struct Entry
    {
        public int Hash;
        public int Next; // index + 1, 0 ends the chain
        public GCHandle Handle;
    }

    /// <summary>Entries currently held, including ones whose object has died since the last sweep.</summary>
    public int Count
    {
        get
        {
            lock (_lock) return _count;
        }
    }

    public T GetOrAdd(T candidate) => GetOrAdd(comparer.GetHashCode(candidate), new Candidate(candidate, comparer));

    /// <summary>An object already made, as the key of itself.</summary>
    private readonly struct Candidate(T value, IEqualityComparer<T> comparer) : IInternKey<T>
    {
        public bool Describes(T existing) => comparer.Equals(existing, value);

        public T Create() => value;
    }

    /// <summary>
    /// The live object the key describes, or a new one the key creates: a look-up that allocates
    /// nothing when the object exists, which is most of the time. <paramref name="hash"/> must be
    /// the comparer's hash of the object the key describes.
    /// </summary>
    public T GetOrAdd<TKey>(int hash, TKey key) where TKey : IInternKey<T>
    {
        lock (_lock)
        {
            var bucket = hash & (_buckets.Length - 1);
            for (var i = _buckets[bucket]; i != 0; i = _entries[i - 1].Next)
            {
                ref var entry = ref _entries[i - 1];
                if (entry.Hash == hash && entry.Handle.Target is T existing && key.Describes(existing))
                    return existing;
            }
            return Add(hash, bucket, key.Create());
        }
    }

    /// <summary>Adopts a candidate known to be new; called under the lock.</summary>
    private T Add(int hash, int bucket, T candidate)
    {
        if (_count == _sweepThreshold)
        {
            SweepAndResize();
            bucket = hash & (_buckets.Length - 1);
        }
        else if (_count == _entries.Length)
        {
            Resize(_entries.Length * 2);
            bucket = hash & (_buckets.Length - 1);
        }
        _entries[_count] = new Entry { Hash = hash, Next = _buckets[bucket], Handle = GCHandle.Alloc(candidate, GCHandleType.Weak) };
        _buckets[bucket] = ++_count;
        return candidate;
    }

    private void SweepAndResize()
    {
        var live = 0;
        for (var i = 0; i < _count; i++)
        {
            if (_entries[i].Handle.Target is null) _entries[i].Handle.Free();
            else _entries[live++] = _entries[i];
        }
        Array.Clear(_entries, live, _count - live);
        _count = live;
        _sweepThreshold = Math.Max(MinimumSweepThreshold, 2 * live);
        var capacity = _entries.Length;
        while (capacity < _sweepThreshold) capacity *= 2;
        Resize(capacity);
    }

    private void Resize(int capacity)
    {
        if (capacity != _entries.Length) Array.Resize(ref _entries, capacity);
        _buckets = new int[capacity];
        for (var i = 0; i < _count; i++)
        {
            var bucket = _entries[i].Hash & (capacity - 1);
            _entries[i].Next = _buckets[bucket];
            _buckets[bucket] = i + 1;
        }
    }
}
