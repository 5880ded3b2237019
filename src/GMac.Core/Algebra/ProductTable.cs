using System.Collections.Concurrent;
using System.Numerics;
using System.Runtime.CompilerServices;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// The exact blade products of one frame and one product kind, with coefficients converted once
/// to the scalar type T, so a multivector product is only table look-ups, multiplies and adds.
/// </summary>
internal sealed class ProductTable<T> where T : INumberBase<T>
{
    private const int DenseLimit = 256; // blade counts up to 8 dimensions get a flat array of entries

    private static readonly ConditionalWeakTable<Frame, ProductTable<T>[]> Tables = new();

    private readonly Frame _frame;
    private readonly ProductKind _kind;
    private readonly Entry?[]? _dense;
    private readonly ConcurrentDictionary<long, Entry>? _sparse;

    /// <summary>Frames up to this many blades (6 dimensions) also get every entry in three flat arrays.</summary>
    private const int FlatLimit = 64;

    private Flat? _flat;
    private int _built; // entries of _dense filled so far

    /// <summary>
    /// All entries in compressed rows: the terms of blade pair (a, b) are at Start[p] .. Start[p + 1] − 1
    /// of Blades and Coefficients, with p = a · bladeCount + b. One load per pair instead of an entry object.
    /// </summary>
    internal sealed class Flat(int[] start, int[] blades, T[] coefficients)
    {
        public readonly int[] Start = start;
        public readonly int[] Blades = blades;
        public readonly T[] Coefficients = coefficients;
    }

    /// <summary>
    /// The flat form for frames of at most 64 blades, once products have built every entry; null
    /// until then. Symbolic code generation in a fresh frame needs only the pairs its operands
    /// meet, so the table is never completed just to be flattened.
    /// </summary>
    public Flat? Flattened()
    {
        if (_flat is not null || _frame.BladeCount > FlatLimit) return _flat;
        var n = _frame.BladeCount;
        if (Volatile.Read(ref _built) < n * n) return null;
        var start = new int[n * n + 1];
        var blades = new List<int>();
        var coefficients = new List<T>();
        for (var a = 0; a < n; a++)
        for (var b = 0; b < n; b++)
        {
            var entry = Get(a, b);
            start[a * n + b] = blades.Count;
            blades.AddRange(entry.Blades);
            coefficients.AddRange(entry.Coefficients);
        }
        start[n * n] = blades.Count;
        return _flat = new Flat(start, blades.ToArray(), coefficients.ToArray()); // a benign race, as in Get
    }

    /// <summary>
    /// The flat form, building every entry first: for numeric products, which meet every pair of
    /// blades anyway. Null for frames above 64 blades.
    /// </summary>
    public Flat? Completed()
    {
        if (_flat is not null || _frame.BladeCount > FlatLimit) return _flat;
        var n = _frame.BladeCount;
        for (var a = 0; a < n; a++)
        for (var b = 0; b < n; b++)
            Get(a, b);
        return Flattened();
    }

    internal sealed class Entry(int[] blades, T[] coefficients, bool[] isOne)
    {
        public readonly int[] Blades = blades;
        public readonly T[] Coefficients = coefficients;
        public readonly bool[] IsOne = isOne;
    }

    private ProductTable(Frame frame, ProductKind kind)
    {
        _frame = frame;
        _kind = kind;
        if (frame.BladeCount <= DenseLimit) _dense = new Entry?[frame.BladeCount * frame.BladeCount];
        else _sparse = new ConcurrentDictionary<long, Entry>();
    }

    public static ProductTable<T> For(Frame frame, ProductKind kind)
    {
        var tables = Tables.GetValue(frame, f =>
        {
            var kinds = Enum.GetValues<ProductKind>();
            var array = new ProductTable<T>[kinds.Length];
            foreach (var k in kinds) array[(int)k] = new ProductTable<T>(f, k);
            return array;
        });
        return tables[(int)kind];
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Entry Get(int a, int b)
    {
        if (_dense is not null)
        {
            var index = a * _frame.BladeCount + b;
            if (_dense[index] is { } known) return known;
            var entry = Build(a, b);
            // A benign race: both builders produce equal entries; only the first one stored is counted.
            if (Interlocked.CompareExchange(ref _dense[index], entry, null) is { } other) return other;
            Interlocked.Increment(ref _built);
            return entry;
        }
        return _sparse!.GetOrAdd(((long)a << 32) | (uint)b, key => Build((int)(key >> 32), (int)key));
    }

    private Entry Build(int a, int b)
    {
        var terms = _frame.Products.Product(_kind, a, b);
        var blades = new int[terms.Length];
        var coefficients = new T[terms.Length];
        var isOne = new bool[terms.Length];
        for (var i = 0; i < terms.Length; i++)
        {
            blades[i] = terms[i].Blade;
            coefficients[i] = Convert(terms[i].Coefficient);
            isOne[i] = terms[i].Coefficient.IsOne;
        }
        return new Entry(blades, coefficients, isOne);
    }

    public static T Convert(Rational r)
    {
        var n = r.IsInteger ? T.CreateChecked(r.Numerator) : T.CreateChecked(r.Numerator) / T.CreateChecked(r.Denominator);
        return n;
    }
}
