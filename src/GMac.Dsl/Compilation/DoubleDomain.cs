using GMac.Core.Numerics;

namespace GMac.Dsl.Compilation;

/// <summary>Plain floating point: the numeric reference for compiled macros.</summary>
public sealed class DoubleDomain : IScalarDomain<double>
{
    public static readonly DoubleDomain Instance = new();

    public double FromRational(Rational value) => value.ToDouble();
    public double Pi => Math.PI;
    public double Exp(double x) => Math.Exp(x);
    public double Log(double x) => Math.Log(x);
    public double Atan2(double y, double x) => Math.Atan2(y, x);
    public double Pow(double x, double y) => Math.Pow(x, y);
}
