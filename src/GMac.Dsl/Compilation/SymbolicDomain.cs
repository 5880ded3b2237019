using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Dsl.Compilation;

/// <summary>Symbolic scalars: what the code generator evaluates macros on.</summary>
public sealed class SymbolicDomain : IScalarDomain<Scalar>
{
    public static readonly SymbolicDomain Instance = new();

    public Scalar FromRational(Rational value) => Scalar.Constant(value);
    public Scalar Pi => Scalar.Pi;
    public Scalar Exp(Scalar x) => Scalar.Exp(x);
    public Scalar Log(Scalar x) => Scalar.Log(x);
    public Scalar Atan2(Scalar y, Scalar x) => Scalar.Atan2(y, x);
    public Scalar Pow(Scalar x, Scalar y) =>
        y.TryGetConstant(out var n) && n.IsInteger && n.Abs() <= 64 ? Scalar.Pow(x, (int)n.Numerator) : Scalar.Pow(x, y);
}
