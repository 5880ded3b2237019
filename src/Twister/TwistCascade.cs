namespace Twister;

/// <summary>
/// Twists applied in order, first to last (thesis §6.4.1): the versor V(u, v) = V_n ⋯ V_1 of a curve
/// or surface. Immutable; each builder method returns a longer cascade.
/// </summary>
public sealed class TwistCascade
{
    private readonly Twist[] _twists;

    public TwistCascade(params IEnumerable<Twist> twists)
    {
        Require.NotNull(twists, nameof(twists));
        _twists = [.. twists];
        for (var i = 0; i < _twists.Length; i++) Require.NotNull(_twists[i], $"twists[{i}]");
    }

    public static TwistCascade Empty { get; } = new();

    public IReadOnlyList<Twist> Twists => _twists;

    public bool IgnoresV => _twists.All(t => t.IgnoresV);

    public TwistCascade Then(Twist twist)
    {
        Require.NotNull(twist, nameof(twist));
        return new([.. _twists, twist]);
    }

    public TwistCascade Then(TwistCascade cascade)
    {
        Require.NotNull(cascade, nameof(cascade));
        return new([.. _twists, .. cascade._twists]);
    }

    public TwistCascade RotateAboutX(double coefficient, ParameterMap map) => Then(RotationTwist.AboutX(coefficient, map));
    public TwistCascade RotateAboutY(double coefficient, ParameterMap map) => Then(RotationTwist.AboutY(coefficient, map));
    public TwistCascade RotateAboutZ(double coefficient, ParameterMap map) => Then(RotationTwist.AboutZ(coefficient, map));

    public TwistCascade RotateAbout(TwistableVector axis, TwistablePoint origin, double coefficient, ParameterMap map) =>
        Then(new RotationTwist(axis, origin, coefficient, map));

    public TwistCascade Translate(TwistableVector vector, double coefficient, ParameterMap map) =>
        Then(new TranslationTwist(vector, coefficient, map));

    /// <summary>
    /// Every member transformed by <paramref name="by"/> (at its parameters (u, v)): the cascade of
    /// by ∘ V ∘ by⁻¹, i.e. the same shape moved by <paramref name="by"/> when its seed is moved too.
    /// </summary>
    public TwistCascade TransformedBy(Twist by, double u = 0, double v = 0)
    {
        Require.NotNull(by, nameof(by));
        return new(_twists.Select(t => by.Apply(t, u, v)));
    }

    /// <summary>The hot path of curves and surfaces: the common sealed twists are called directly, not virtually.</summary>
    public TwistablePoint Apply(TwistablePoint p, double u, double v)
    {
        foreach (var twist in _twists)
        {
            p = twist switch
            {
                RotationTwist rotation => rotation.Apply(p, u, v),
                FullTwist full => full.Apply(p, u, v),
                TranslationTwist translation => translation.Apply(p, u, v),
                _ => twist.Apply(p, u, v),
            };
        }
        return p;
    }

    public TwistableVector Apply(TwistableVector d, double u, double v)
    {
        foreach (var twist in _twists) d = twist.Apply(d, u, v);
        return d;
    }

    public TwistableBivector Apply(TwistableBivector b, double u, double v)
    {
        foreach (var twist in _twists) b = twist.Apply(b, u, v);
        return b;
    }

    /// <summary>
    /// The moved point and its partial derivatives ∂/∂u, ∂/∂v by the product rule, twist by twist;
    /// the seed is constant, so both start at zero.
    /// </summary>
    public TwistablePoint ApplyWithTangents(TwistablePoint seed, double u, double v, out TwistableVector du, out TwistableVector dv)
    {
        var p = seed;
        du = default;
        dv = default;
        foreach (var twist in _twists) twist.ApplyWithTangents(ref p, ref du, ref dv, u, v);
        return p;
    }

    /// <summary><see cref="ApplyWithTangents"/> for ∂/∂u alone, what a curve needs.</summary>
    public TwistablePoint ApplyWithTangent(TwistablePoint seed, double u, double v, out TwistableVector du)
    {
        var p = seed;
        du = default;
        foreach (var twist in _twists) twist.ApplyWithTangent(ref p, ref du, u, v);
        return p;
    }
}
