namespace Twister;

/// <summary>
/// A surface S(u, v) = V(u, v) p V(u, v)⁻¹ (thesis (6.8)): the orbit of a seed point under one cascade
/// in u and v. (s, t) ∈ [0, 1]² runs over u ∈ [<see cref="UStart"/>, <see cref="UEnd"/>] and
/// v ∈ [<see cref="VStart"/>, <see cref="VEnd"/>].
/// </summary>
public sealed class SingleTwistSurface : IParametricSurface
{
    public SingleTwistSurface(TwistablePoint seed, TwistCascade cascade, double uStart = 0, double uEnd = 1, double vStart = 0, double vEnd = 1)
    {
        Require.Finite(seed, nameof(seed));
        Require.NotNull(cascade, nameof(cascade));
        Require.Finite(uStart, nameof(uStart));
        Require.Finite(uEnd, nameof(uEnd));
        Require.Finite(vStart, nameof(vStart));
        Require.Finite(vEnd, nameof(vEnd));
        Seed = seed;
        Cascade = cascade;
        UStart = uStart;
        UEnd = uEnd;
        VStart = vStart;
        VEnd = vEnd;
    }

    public TwistablePoint Seed { get; }
    public TwistCascade Cascade { get; }
    public double UStart { get; }
    public double UEnd { get; }
    public double VStart { get; }
    public double VEnd { get; }

    public TwistablePoint PointAt(double u, double v)
    {
        Require.Parameters(u, v);
        return Cascade.Apply(Seed, UStart + u * (UEnd - UStart), VStart + v * (VEnd - VStart));
    }

    /// <summary>The tangent plane B = ∂S/∂u ^ ∂S/∂v over the unit square (6.10).</summary>
    public TwistableBivector TangentPlaneAt(double u, double v)
    {
        Require.Parameters(u, v);
        Cascade.ApplyWithTangents(Seed, UStart + u * (UEnd - UStart), VStart + v * (VEnd - VStart), out var su, out var sv);
        double a = UEnd - UStart, b = VEnd - VStart;
        return TwistableBivector.Span(new(su.x * a, su.y * a, su.z * a), new(sv.x * b, sv.y * b, sv.z * b));
    }

    /// <summary>N = B ⌋ I3⁻¹ (6.10).</summary>
    public TwistableVector NormalAt(double u, double v) => TangentPlaneAt(u, v).Normal();
}
