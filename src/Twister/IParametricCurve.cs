namespace Twister;

/// <summary>A curve over the parameter interval t ∈ [0, 1]; what tessellation and rendering need of it.</summary>
public interface IParametricCurve
{
    TwistablePoint PointAt(double t);

    /// <summary>∂U/∂t, not normalised; it vanishes where the curve stops.</summary>
    TwistableVector TangentAt(double t);
}
