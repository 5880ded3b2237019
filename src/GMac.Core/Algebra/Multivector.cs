using System.Numerics;
using System.Text;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// An immutable multivector of a frame, generic over its scalar type: <c>double</c> for numbers,
/// the symbolic <c>Scalar</c> for code generation. Two storage forms, fixed by the scalar type
/// and the frame:
/// <list type="bullet">
/// <item>Dense: value-type scalars (double, float) in frames of at most 8 dimensions keep one
/// coefficient per blade, 2^n in blade-id order, zeros included. A product is two loops over
/// the blades with the sign or blade-product table of the frame, adding straight into the
/// result's array: no sorting, no look-ups by id, no allocation beyond the result.</item>
/// <item>Sparse: symbolic scalars, and larger frames, keep the non-zero terms sorted by blade id.
/// A conformal point has 5 of 32 symbolic coefficients, and a product loops over the terms
/// present only, adding into a dense per-thread buffer (see <see cref="Accumulator"/>).</item>
/// </list>
/// Either way exact zeros are not terms: <see cref="Terms"/> and <see cref="TermCount"/> see only
/// non-zero coefficients. Every operation is written once for both scalar domains.
/// </summary>
public sealed partial class Multivector<T>
    where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
{
    // The sparse form; both empty in the dense form.
    private readonly int[] _ids;
    private readonly T[] _coefficients;

    // The dense form: one coefficient per blade id; null in the sparse form.
    private readonly T[]? _dense;

    public Frame Frame { get; }

    private Multivector(Frame frame, int[] ids, T[] coefficients)
    {
        Frame = frame;
        _ids = ids;
        _coefficients = coefficients;
    }

    private Multivector(Frame frame, T[] dense)
    {
        Frame = frame;
        _ids = [];
        _coefficients = [];
        _dense = dense;
    }

    // ---- construction ----------------------------------------------------------------------

    public static Multivector<T> Zero(Frame frame) => IsDenseFrame(frame) ? new(frame, new T[frame.BladeCount]) : new(frame, [], []);

    public static Multivector<T> FromScalar(Frame frame, T value) => Basis(frame, BasisBlade.Scalar, value);

    public static Multivector<T> Basis(Frame frame, BasisBlade blade) => Basis(frame, blade, T.One);

    public static Multivector<T> Basis(Frame frame, BasisBlade blade, T coefficient)
    {
        frame.CheckBlade(blade);
        if (IsDenseFrame(frame))
        {
            var dense = new T[frame.BladeCount];
            dense[blade.Id] = coefficient;
            return new Multivector<T>(frame, dense);
        }
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
        if (IsDenseFrame(frame))
        {
            var dense = new T[frame.BladeCount];
            for (var i = 0; i < coefficients.Length; i++) dense[1 << i] = coefficients[i];
            return new Multivector<T>(frame, dense);
        }
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
        if (IsDenseFrame(frame))
        {
            var dense = new T[frame.BladeCount];
            foreach (var (blade, c) in terms)
            {
                frame.CheckBlade(blade);
                dense[blade.Id] += c;
            }
            return new Multivector<T>(frame, dense);
        }
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

    public int TermCount => _dense is null ? _ids.Length : DenseTermCount(_dense);
    public bool IsZero => _dense is null ? _ids.Length == 0 : DenseTermCount(_dense) == 0;

    public IEnumerable<(BasisBlade Blade, T Coefficient)> Terms
    {
        get
        {
            if (_dense is not null)
            {
                for (var id = 0; id < _dense.Length; id++)
                    if (!T.IsZero(_dense[id])) yield return (new BasisBlade(id), _dense[id]);
                yield break;
            }
            for (var i = 0; i < _ids.Length; i++) yield return (new BasisBlade(_ids[i]), _coefficients[i]);
        }
    }

    public T this[BasisBlade blade]
    {
        get
        {
            if (_dense is not null) return (uint)blade.Id < (uint)_dense.Length && !T.IsZero(_dense[blade.Id]) ? _dense[blade.Id] : T.Zero;
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
            foreach (var id in Ids()) mask |= 1 << BitOperations.PopCount((uint)id);
            var grades = new int[BitOperations.PopCount((uint)mask)];
            for (var k = 0; mask != 0; mask &= mask - 1) grades[k++] = BitOperations.TrailingZeroCount(mask);
            return grades;
        }
    }

    public bool IsScalar => _dense is null ? _ids.Length == 0 || (_ids.Length == 1 && _ids[0] == 0) : DenseTermCount(_dense, 1) == 0;

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
        if (_dense is not null) return DenseMap(c => s * c);
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
        if (a._dense is not null) return DenseCombine(a, b._dense!, subtract);
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
        if (_dense is not null) return DenseMap(f);
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
        where TOther : INumberBase<TOther>, IRootFunctions<TOther>, ITrigonometricFunctions<TOther>, IHyperbolicFunctions<TOther>
    {
        var ids = _dense is null ? _ids : Ids().ToArray();
        var cs = _dense is null ? _coefficients : Array.ConvertAll(ids, id => _dense[id]);
        return Multivector<TOther>.FromSortedTerms(Frame, ids, Array.ConvertAll(cs, c => convert(c)));
    }

    /// <summary>Terms already sorted by distinct blade ids; zero coefficients are dropped.</summary>
    internal static Multivector<T> FromSortedTerms(Frame frame, int[] ids, T[] coefficients)
    {
        if (IsDenseFrame(frame))
        {
            var dense = new T[frame.BladeCount];
            for (var i = 0; i < ids.Length; i++) dense[ids[i]] = coefficients[i];
            return new Multivector<T>(frame, dense);
        }
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
        foreach (var (blade, coefficient) in Terms)
        {
            if (sb.Length > 0) sb.Append(" + ");
            var c = coefficient.ToString();
            var needsParens = c is not null && (c.Contains('+') || c.IndexOf('-', 1) > 0);
            sb.Append(needsParens ? $"({c})" : c);
            if (blade.Id != 0) sb.Append(' ').Append(Frame.BladeName(blade));
        }
        return sb.ToString();
    }
}
