using System.Runtime.CompilerServices;

namespace Twister;

/// <summary>
/// A twist parameter θ = c·f(u, v): a coefficient times a parameter map, with the affine case
/// folded once (θ = a·u + b·v + k) so the hot path neither multiplies twice nor calls a delegate.
/// </summary>
internal readonly struct ScaledMap
{
    private readonly double _a, _b, _k, _coefficient;
    private readonly ParameterMap? _function;

    public ScaledMap(double coefficient, ParameterMap map)
    {
        _coefficient = coefficient;
        if (map.IsAffine)
        {
            _a = coefficient * map.A;
            _b = coefficient * map.B;
            _k = coefficient * map.C;
        }
        else _function = map;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double At(double u, double v) => _function is null ? _a * u + _b * v + _k : _coefficient * _function.Evaluate(u, v);

    public double DerivativeU(double u, double v) => _function is null ? _a : _coefficient * _function.DerivativeU(u, v);

    public double DerivativeV(double u, double v) => _function is null ? _b : _coefficient * _function.DerivativeV(u, v);
}
