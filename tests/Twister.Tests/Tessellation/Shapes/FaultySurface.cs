namespace Twister.Tests.Tessellation.Shapes;

/// <summary>A plane that gives NaN in one corner of its parameter square, as a broken formula would.</summary>
internal sealed class FaultySurface : IParametricSurface
{
    public TwistablePoint PointAt(double u, double v) => u > 0.6 && v > 0.6 ? new(double.NaN, v, 0) : new(u, v, 0);

    public TwistableVector NormalAt(double u, double v) => new(0, 0, 1);
}
