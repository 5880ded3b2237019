namespace Twister;

/// <summary>
/// A curve U(u) = V(u) p V(u)⁻¹ (thesis (6.2)): the orbit of a seed point under a cascade whose maps
/// depend on u only. t ∈ [0, 1] runs over u ∈ [<see cref="UStart"/>, <see cref="UEnd"/>].
/// </summary>
public sealed class TwistCurve : IParametricCurve
{
    public TwistCurve(TwistablePoint seed, TwistCascade cascade, double uStart = 0, double uEnd = 1)
    {
        Require.Finite(seed, nameof(seed));
        Require.NotNull(cascade, nameof(cascade));
        Require.Finite(uStart, nameof(uStart));
        Require.Finite(uEnd, nameof(uEnd));
        if (!cascade.IgnoresV)
            throw new ArgumentException("a curve's twists must not depend on v", nameof(cascade));
        Seed = seed;
        Cascade = cascade;
        UStart = uStart;
        UEnd = uEnd;
    }

    public TwistablePoint Seed { get; }
    public TwistCascade Cascade { get; }
    public double UStart { get; }
    public double UEnd { get; }

    /// <summary>The curve parameter u at t.</summary>
    public double ParameterAt(double t)
    {
        Require.Finite(t, nameof(t));
        return UStart + t * (UEnd - UStart);
    }

    public TwistablePoint PointAt(double t) => Cascade.Apply(Seed, ParameterAt(t), 0);

    /// <summary>(6.4) N(t) = ∂U/∂t = (u₁ − u₀) ∂U/∂u.</summary>
    public TwistableVector TangentAt(double t)
    {
        PointAndTangentAt(t, out var tangent);
        return tangent;
    }

    /// <summary>U(t) and N(t) from one pass over the cascade.</summary>
    public TwistablePoint PointAndTangentAt(double t, out TwistableVector tangent)
    {
        var p = Cascade.ApplyWithTangent(Seed, ParameterAt(t), 0, out var du);
        var scale = UEnd - UStart;
        tangent = new(du.x * scale, du.y * scale, du.z * scale);
        return p;
    }
}
