using System.Numerics;
using System.Text;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// An immutable multivector of a frame, generic over its scalar type: <c>double</c> for numbers,
/// the symbolic <c>Scalar</c> for code generation. Terms are kept sparse, sorted by blade id,
/// with exact zeros dropped: a conformal point has 5 of 32 coefficients, and products loop over
/// the terms present only. Products add into a dense per-thread buffer indexed by blade and read
/// signs from per-frame tables (see <see cref="Accumulator"/> and the product partial), so an
/// operation allocates its result and nothing else. Every operation is written once for both domains.
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
        var count = 0;
        foreach (var c in coefficients)
            if (!T.IsZero(c)) count++;
        var ids = new int[count];
        var cs = new T[count];
        for (int i = 0, k = 0; i < coefficients.Length; i++)
        {
            if (T.IsZero(coefficients[i])) continue;
            ids[k] = 1 << i;
            cs[k++] = coefficients[i];
        }
        return new Multivector<T>(frame, ids, cs);
    }

    /// <summary>A multivector from (blade, coefficient) pairs; repeated blades are summed.</summary>
    public static Multivector<T> FromTerms(Frame frame, IEnumerable<(BasisBlade Blade, T Coefficient)> terms)
    {
        var acc = Accumulator.Rent(frame);
        try
        {
            foreach (var (blade, c) in terms)
            {
                frame.CheckBlade(blade);
                acc.Add(blade.Id, c);
            }
            return acc.ToMultivector(frame);
        }
        finally
        {
            acc.Return();
        }
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
    public IReadOnlyList<int> Grades
    {
        get
        {
            var mask = 0;
            foreach (var id in _ids) mask |= 1 << BitOperations.PopCount((uint)id);
            var grades = new int[BitOperations.PopCount((uint)mask)];
            for (var k = 0; mask != 0; mask &= mask - 1) grades[k++] = BitOperations.TrailingZeroCount(mask);
            return grades;
        }
    }

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

    public Multivector<T> Scale(T s)
    {
        if (T.IsZero(s)) return Zero(Frame);
        var ids = new int[_ids.Length];
        var cs = new T[_ids.Length];
        var k = 0;
        for (var i = 0; i < _ids.Length; i++)
        {
            var c = s * _coefficients[i];
            if (T.IsZero(c)) continue; // a product of non-zero doubles can underflow to zero
            ids[k] = _ids[i];
            cs[k++] = c;
        }
        return Trimmed(Frame, ids, cs, k);
    }

    public Multivector<T> Add(T scalar) => this + FromScalar(Frame, scalar);

    private static Multivector<T> Combine(Multivector<T> a, Multivector<T> b, bool subtract)
    {
        RequireSameFrame(a, b, subtract ? "subtract" : "add");
        var (x, y) = (a._ids, b._ids);
        var ids = new int[x.Length + y.Length];
        var cs = new T[ids.Length];
        int i = 0, j = 0, k = 0;
        while (i < x.Length || j < y.Length)
        {
            if (j >= y.Length || (i < x.Length && x[i] < y[j]))
            {
                ids[k] = x[i]; cs[k++] = a._coefficients[i++];
            }
            else if (i >= x.Length || y[j] < x[i])
            {
                ids[k] = y[j]; cs[k++] = subtract ? -b._coefficients[j] : b._coefficients[j]; j++;
            }
            else
            {
                var c = subtract ? a._coefficients[i] - b._coefficients[j] : a._coefficients[i] + b._coefficients[j];
                if (!T.IsZero(c)) { ids[k] = x[i]; cs[k++] = c; }
                i++; j++;
            }
        }
        return Trimmed(a.Frame, ids, cs, k);
    }

    /// <summary>A multivector of the first <paramref name="count"/> terms, copied only when the arrays are longer.</summary>
    private static Multivector<T> Trimmed(Frame frame, int[] ids, T[] cs, int count)
    {
        if (count != ids.Length)
        {
            Array.Resize(ref ids, count);
            Array.Resize(ref cs, count);
        }
        return new Multivector<T>(frame, ids, cs);
    }

    /// <summary>Applies f to every coefficient, dropping those that become zero.</summary>
    public Multivector<T> MapCoefficients(Func<T, T> f)
    {
        var ids = new int[_ids.Length];
        var cs = new T[_ids.Length];
        var k = 0;
        for (var i = 0; i < _ids.Length; i++)
        {
            var c = f(_coefficients[i]);
            if (T.IsZero(c)) continue;
            ids[k] = _ids[i];
            cs[k++] = c;
        }
        return Trimmed(Frame, ids, cs, k);
    }

    /// <summary>Applies f(blade, coefficient) to every term.</summary>
    public Multivector<T> MapTerms(Func<BasisBlade, T, T> f) => FromTerms(Frame, Terms.Select(t => (t.Blade, f(t.Blade, t.Coefficient))));

    /// <summary>The same coefficients carried to another scalar type (e.g. symbolic to numeric).</summary>
    public Multivector<TOther> Convert<TOther>(Func<T, TOther> convert)
        where TOther : INumberBase<TOther>, IRootFunctions<TOther>, ITrigonometricFunctions<TOther>, IHyperbolicFunctions<TOther> =>
        Multivector<TOther>.FromSortedTerms(Frame, _ids, Array.ConvertAll(_coefficients, c => convert(c)));

    /// <summary>Terms already sorted by distinct blade ids; zero coefficients are dropped.</summary>
    internal static Multivector<T> FromSortedTerms(Frame frame, int[] ids, T[] coefficients)
    {
        var keptIds = new int[ids.Length];
        var k = 0;
        for (var i = 0; i < ids.Length; i++)
        {
            if (T.IsZero(coefficients[i])) continue;
            keptIds[k] = ids[i];
            coefficients[k++] = coefficients[i];
        }
        return Trimmed(frame, keptIds, coefficients, k);
    }

    internal static void RequireSameFrame(Multivector<T> a, Multivector<T> b, string operation)
    {
        if (!ReferenceEquals(a.Frame, b.Frame))
            throw new AlgebraException(a.Frame.Name, $"cannot {operation} a multivector of frame '{a.Frame.Name}' and one of frame '{b.Frame.Name}'; map one into the other's frame first.");
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
