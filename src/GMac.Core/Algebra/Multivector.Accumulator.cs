using System.Numerics;

namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    /// <summary>
    /// Collects terms by blade for a product: a dense array indexed by blade id for frames up to
    /// 12 dimensions, a dictionary above. One accumulator per thread is kept and reused, so a
    /// product allocates only its result; a nested use while it is out gets a fresh one.
    /// </summary>
    private sealed class Accumulator
    {
        private const int DenseLimit = 4096;

        [ThreadStatic] private static Accumulator? _spare;

        private T[] _values = [];
        private bool[] _used = [];
        private int[] _touched = [];
        private int _count;
        private Dictionary<int, T>? _sparse;

        public static Accumulator Rent(Frame frame)
        {
            var acc = _spare ?? new Accumulator();
            _spare = null;
            if (frame.BladeCount <= DenseLimit)
            {
                acc._sparse = null;
                if (acc._values.Length < frame.BladeCount)
                {
                    acc._values = new T[frame.BladeCount];
                    acc._used = new bool[frame.BladeCount];
                    acc._touched = new int[frame.BladeCount];
                }
            }
            else acc._sparse = new Dictionary<int, T>();
            return acc;
        }

        /// <summary>Clears what was added and keeps the buffers for the next product on this thread.</summary>
        public void Return()
        {
            for (var i = 0; i < _count; i++)
            {
                _used[_touched[i]] = false;
                _values[_touched[i]] = default!;
            }
            _count = 0;
            _sparse = null;
            _spare = this;
        }

        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public void Add(int id, T value)
        {
            if (_sparse is not null)
            {
                _sparse[id] = _sparse.TryGetValue(id, out var old) ? old + value : value;
                return;
            }
            if (_used[id])
            {
                _values[id] += value;
                return;
            }
            _values[id] = value;
            _used[id] = true;
            _touched[_count++] = id;
        }

        public Multivector<T> ToMultivector(Frame frame)
        {
            if (_sparse is not null)
            {
                var sorted = _sparse.Where(kv => !T.IsZero(kv.Value)).OrderBy(kv => kv.Key).ToArray();
                return new Multivector<T>(frame, Array.ConvertAll(sorted, kv => kv.Key), Array.ConvertAll(sorted, kv => kv.Value));
            }
            // Few blades touched in a large frame: sort them; otherwise a scan in id order is cheaper.
            if (_count * 8 < frame.BladeCount) Array.Sort(_touched, 0, _count);
            else
            {
                var k = 0;
                for (var id = 0; id < frame.BladeCount && k < _count; id++)
                    if (_used[id]) _touched[k++] = id;
            }
            var nonZero = 0;
            for (var i = 0; i < _count; i++)
                if (!T.IsZero(_values[_touched[i]])) nonZero++;
            var ids = new int[nonZero];
            var cs = new T[nonZero];
            for (int i = 0, k = 0; i < _count; i++)
            {
                var id = _touched[i];
                if (T.IsZero(_values[id])) continue;
                ids[k] = id;
                cs[k++] = _values[id];
            }
            return new Multivector<T>(frame, ids, cs);
        }
    }
}
