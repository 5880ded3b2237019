namespace Twister;

/// <summary>A surface over the unit square (u, v) ∈ [0, 1]²; what tessellation and rendering need of it.</summary>
public interface IParametricSurface
{
    TwistablePoint PointAt(double u, double v);

    /// <summary>
    /// The dual of the tangent bivector ∂S/∂u ∧ ∂S/∂v, not normalised; it vanishes where the
    /// parametrization is singular (the poles of a sphere).
    /// </summary>
    TwistableVector NormalAt(double u, double v);
}
