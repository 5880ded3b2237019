using System.Globalization;
using System.Runtime.CompilerServices;

namespace RayTracer.Maths;

/// <summary>
/// Member bodies shared by the <see cref="ITuple3{TSelf}"/> types, written once: equality, hashing, text,
/// scaling, and the length and normalisation of the two direction types. Generic over the value type, so
/// the JIT specialises each call for it (no boxing, inlined like the hand-written copies it replaces).
/// </summary>
internal static class Tuple3
{
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Equal<T>(in T a, in T b) where T : struct, ITuple3<T>
    {
        var (a0, a1, a2) = a.Components;
        var (b0, b1, b2) = b.Components;
        return a0 == b0 && a1 == b1 && a2 == b2;
    }

    public static int Hash<T>(in T a) where T : struct, ITuple3<T>
    {
        var (a0, a1, a2) = a.Components;
        return HashCode.Combine(a0, a1, a2);
    }

    /// <summary>The components between <paramref name="open"/> and <paramref name="close"/>, invariant culture.</summary>
    public static string Format<T>(in T a, string open, string close) where T : struct, ITuple3<T>
    {
        var (a0, a1, a2) = a.Components;
        return string.Create(CultureInfo.InvariantCulture, $"{open}{a0}, {a1}, {a2}{close}");
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static T Scale<T>(in T a, double s) where T : struct, ITuple3<T>
    {
        var (a0, a1, a2) = a.Components;
        return T.Create(a0 * s, a1 * s, a2 * s);
    }

    /// <summary>Division as multiplication by the reciprocal (one division instead of three).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static T Divide<T>(in T a, double s) where T : struct, ITuple3<T> => Scale(a, 1.0 / s);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double LengthSquared<T>(in T a) where T : struct, ITuple3<T>
    {
        var (a0, a1, a2) = a.Components;
        return a0 * a0 + a1 * a1 + a2 * a2;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static T Normalized<T>(in T a) where T : struct, ITuple3<T> => Scale(a, 1.0 / Math.Sqrt(LengthSquared(a)));
}
