using System.Numerics;
using System.Text;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// An immutable multivector of a frame, generic over its scalar type: <c>double</c> for numbers,
/// the symbolic <c>Scalar</c> for code generation. Terms are kept sparse, sorted by blade id,
/// with exact zeros dropped. Every operation is written once for both domains.
/// </summary>
public sealed partial class Multivector<T>
    where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
{
    private readonly int[] _ids;
    private readonly T[] _coefficients;

    public Frame Frame { get; }

    private Multivector(Frame frame, int[] ids, T[] coefficients)
    {
        Frame = frame;
        _ids = ids;
        _coefficients = coefficients;
    }

    // ---- construction ----------------------------------------------------------------------

    public static Multivector<T> Zero(Frame frame) => new(frame, [], []);

    public static Multivector<T> FromScalar(Frame frame, T value) => Basis(frame, BasisBlade.Scalar, value);

    public static Multivector<T> Basis(Frame frame, BasisBlade blade) => Basis(frame, blade, T.One);

    public static Multivector<T> Basis(Frame frame, BasisBlade blade, T coefficient)
    {
        frame.CheckBlade(blade);
        return T.IsZero(coefficient) ? Zero(frame) : new Multivector<T>(frame, [blade.Id], [coefficient]);
    }

    /// <summary>The blade named like "e1^e2" (any order, the sign follows it).</summary>
    public static Multivector<T> Basis(Frame frame, string bladeName)
    {
        var blade = frame.ParseBlade(bladeName, out var sign);
        return Basis(frame, blade, sign > 0 ? T.One : -T.One);
    }

    /// <summary>The vector Σ cᵢ eᵢ.</summary>
    public static Multivector<T> Vector(Frame frame, params T[] coefficients)
    {
        if (coefficients.Length != frame.Dimension)
            throw new AlgebraException(frame.Name, $"a vector needs {frame.Dimension} coefficients, not {coefficients.Length}.");
        return FromTerms(frame, coefficients.Select((c, i) => (new BasisBlade(1 << i), c)));
    }

    /// <summary>A multivector from (blade, coefficient) pairs; repeated blades are summed.</summary>
    public static Multivector<T> FromTerms(Frame frame, IEnumerable<(BasisBlade Blade, T Coefficient)> terms)
    {
        var acc = new Accumulator(frame);
        foreach (var (blade, c) in terms)
        {
            frame.CheckBlade(blade);
            acc.Add(blade.Id, c);
        }
        return acc.ToMultivector();
    }

    // ---- reading ---------------------------------------------------------------------------

    public int TermCount => _ids.Length;
    public bool IsZero => _ids.Length == 0;

    public IEnumerable<(BasisBlade Blade, T Coefficient)> Terms
    {
        get
        {
            for (var i = 0; i < _ids.Length; i++) yield return (new BasisBlade(_ids[i]), _coefficients[i]);
        }
    }

    public T this[BasisBlade blade]
    {
        get
        {
            var i = Array.BinarySearch(_ids, blade.Id);
            return i >= 0 ? _coefficients[i] : T.Zero;
        }
    }

    /// <summary>The coefficient of a named blade, signed by the order of its name.</summary>
    public T this[string bladeName]
    {
        get
        {
            var blade = Frame.ParseBlade(bladeName, out var sign);
            var c = this[blade];
            return sign > 0 ? c : -c;
        }
    }

    public T ScalarPart => this[BasisBlade.Scalar];

    /// <summary>The distinct grades present, ascending.</summary>
    public IReadOnlyList<int> Grades => _ids.Select(id => BitOperations.PopCount((uint)id)).Distinct().Order().ToArray();

    public bool IsScalar => _ids.Length == 0 || (_ids.Length == 1 && _ids[0] == 0);

    // ---- linear structure ------------------------------------------------------------------

    public static Multivector<T> operator +(Multivector<T> a, Multivector<T> b) => Combine(a, b, false);
    public static Multivector<T> operator -(Multivector<T> a, Multivector<T> b) => Combine(a, b, true);
    public static Multivector<T> operator -(Multivector<T> a) => a.MapCoefficients(c => -c);
    public static Multivector<T> operator *(Multivector<T> a, T s) => a.Scale(s);
    public static Multivector<T> operator *(T s, Multivector<T> a) => a.Scale(s);
    public static Multivector<T> operator /(Multivector<T> a, T s) => a.MapCoefficients(c => c / s);

    /// <summary>The geometric product.</summary>
    public static Multivector<T> operator *(Multivector<T> a, Multivector<T> b) => a.Gp(b);

    public Multivector<T> Scale(T s) => T.IsZero(s) ? Zero(Frame) : MapCoefficients(c => s * c);

    public Multivector<T> Add(T scalar) => this + FromScalar(Frame, scalar);

    private static Multivector<T> Combine(Multivector<T> a, Multivector<T> b, bool subtract)
    {
        RequireSameFrame(a, b, subtract ? "subtract" : "add");
        var ids = new List<int>(a._ids.Length + b._ids.Length);
        var cs = new List<T>(a._ids.Length + b._ids.Length);
        int i = 0, j = 0;
        while (i < a._ids.Length || j < b._ids.Length)
        {
            if (j >= b._ids.Length || (i < a._ids.Length && a._ids[i] < b._ids[j]))
            {
                ids.Add(a._ids[i]); cs.Add(a._coefficients[i]); i++;
            }
            else if (i >= a._ids.Length || b._ids[j] < a._ids[i])
            {
                ids.Add(b._ids[j]); cs.Add(subtract ? -b._coefficients[j] : b._coefficients[j]); j++;
            }
            else
            {
                var c = subtract ? a._coefficients[i] - b._coefficients[j] : a._coefficients[i] + b._coefficients[j];
                if (!T.IsZero(c)) { ids.Add(a._ids[i]); cs.Add(c); }
                i++; j++;
            }
        }
        return new Multivector<T>(a.Frame, ids.ToArray(), cs.ToArray());
    }

    /// <summary>Applies f to every coefficient, dropping those that become zero.</summary>
    public Multivector<T> MapCoefficients(Func<T, T> f)
    {
        var ids = new List<int>(_ids.Length);
        var cs = new List<T>(_ids.Length);
        for (var i = 0; i < _ids.Length; i++)
        {
            var c = f(_coefficients[i]);
            if (T.IsZero(c)) continue;
            ids.Add(_ids[i]);
            cs.Add(c);
        }
        return new Multivector<T>(Frame, ids.ToArray(), cs.ToArray());
    }

    /// <summary>Applies f(blade, coefficient) to every term.</summary>
    public Multivector<T> MapTerms(Func<BasisBlade, T, T> f) => FromTerms(Frame, Terms.Select(t => (t.Blade, f(t.Blade, t.Coefficient))));

    /// <summary>The same coefficients carried to another scalar type (e.g. symbolic to numeric).</summary>
    public Multivector<TOther> Convert<TOther>(Func<T, TOther> convert)
        where TOther : INumberBase<TOther>, IRootFunctions<TOther>, ITrigonometricFunctions<TOther>, IHyperbolicFunctions<TOther> =>
        Multivector<TOther>.FromTerms(Frame, Terms.Select(t => (t.Blade, convert(t.Coefficient))));

    internal static void RequireSameFrame(Multivector<T> a, Multivector<T> b, string operation)
    {
        if (!ReferenceEquals(a.Frame, b.Frame))
            throw new AlgebraException(a.Frame.Name, $"cannot {operation} a multivector of frame '{a.Frame.Name}' and one of frame '{b.Frame.Name}'; map one into the other's frame first.");
    }

    // ---- accumulation buffer for products -----------------------------------------------------

    /// <summary>Collects terms by blade: a dense array for frames up to 12 dimensions, a dictionary above.</summary>
    private struct Accumulator
    {
        private readonly Frame _frame;
        private readonly T[]? _dense;
        private readonly bool[]? _used;
        private readonly Dictionary<int, T>? _sparse;

        public Accumulator(Frame frame)
        {
            _frame = frame;
            if (frame.BladeCount <= 4096)
            {
                _dense = new T[frame.BladeCount];
                _used = new bool[frame.BladeCount];
                _sparse = null;
            }
            else
            {
                _dense = null;
                _used = null;
                _sparse = new Dictionary<int, T>();
            }
        }

        public void Add(int id, T value)
        {
            if (_dense is not null)
            {
                if (_used![id]) _dense[id] += value;
                else { _dense[id] = value; _used[id] = true; }
            }
            else
            {
                _sparse![id] = _sparse.TryGetValue(id, out var old) ? old + value : value;
            }
        }

        public Multivector<T> ToMultivector()
        {
            var ids = new List<int>();
            var cs = new List<T>();
            if (_dense is not null)
            {
                for (var id = 0; id < _dense.Length; id++)
                {
                    if (!_used![id] || T.IsZero(_dense[id])) continue;
                    ids.Add(id);
                    cs.Add(_dense[id]);
                }
            }
            else
            {
                foreach (var kv in _sparse!.OrderBy(kv => kv.Key))
                {
                    if (T.IsZero(kv.Value)) continue;
                    ids.Add(kv.Key);
                    cs.Add(kv.Value);
                }
            }
            return new Multivector<T>(_frame, ids.ToArray(), cs.ToArray());
        }
    }

    // ---- printing ------------------------------------------------------------------------------

    public override string ToString()
    {
        if (IsZero) return "0";
        var sb = new StringBuilder();
        for (var i = 0; i < _ids.Length; i++)
        {
            if (i > 0) sb.Append(" + ");
            var c = _coefficients[i].ToString();
            var needsParens = c is not null && (c.Contains('+') || c.IndexOf('-', 1) > 0);
            sb.Append(needsParens ? $"({c})" : c);
            if (_ids[i] != 0) sb.Append(' ').Append(Frame.BladeName(new BasisBlade(_ids[i])));
        }
        return sb.ToString();
    }
}
