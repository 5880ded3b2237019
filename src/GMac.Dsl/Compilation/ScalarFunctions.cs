using System.Numerics;
using GMac.Dsl.Semantics;

namespace GMac.Dsl.Compilation;

/// <summary>The value of a GMacDSL scalar function in any scalar domain: one table for evaluation and constant folding.</summary>
public static class ScalarFunctions
{
    /// <summary>False for a function this table does not know.</summary>
    public static bool TryApply<T>(ScalarFunction function, IReadOnlyList<T> a, IScalarDomain<T> domain, out T value)
        where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
    {
        var known = true;
        value = function switch
        {
            ScalarFunction.Pi => domain.Pi,
            ScalarFunction.Sin => T.Sin(a[0]),
            ScalarFunction.Cos => T.Cos(a[0]),
            ScalarFunction.Tan => T.Tan(a[0]),
            ScalarFunction.Asin => T.Asin(a[0]),
            ScalarFunction.Acos => T.Acos(a[0]),
            ScalarFunction.Atan => T.Atan(a[0]),
            ScalarFunction.Atan2 => domain.Atan2(a[0], a[1]),
            ScalarFunction.Sinh => T.Sinh(a[0]),
            ScalarFunction.Cosh => T.Cosh(a[0]),
            ScalarFunction.Tanh => T.Tanh(a[0]),
            ScalarFunction.Sqrt => T.Sqrt(a[0]),
            ScalarFunction.Exp => domain.Exp(a[0]),
            ScalarFunction.Log => domain.Log(a[0]),
            ScalarFunction.Abs => T.Abs(a[0]),
            _ => Unknown<T>(out known),
        };
        return known;
    }

    private static T Unknown<T>(out bool known) where T : INumberBase<T>
    {
        known = false;
        return T.Zero;
    }
}
