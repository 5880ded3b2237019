using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Dsl.Compilation;

/// <summary>
/// The scalar operations a macro needs beyond the generic-math interfaces of
/// <c>Multivector&lt;T&gt;</c>: exact constants and the remaining elementary functions.
/// </summary>
public interface IScalarDomain<T>
    where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
{
    T FromRational(Rational value);
    T Pi { get; }
    T Exp(T x);
    T Log(T x);
    T Atan2(T y, T x);
    T Pow(T x, T y);
}
