using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// Random expression trees built twice at once: as a Scalar and as a plain double function, so the
/// canonical form can be checked against direct floating-point evaluation. Operations are guarded
/// (denominators b^2 + 1, roots and logs of positive values) so every tree is defined everywhere.
/// </summary>
internal sealed class RandomExpressionTrees(int seed)
{
    public static readonly string[] VariableNames = ["x0", "x1", "x2"];

    private readonly Random _random = new(seed);

    public (Scalar Symbolic, Func<double[], double> Direct) Next(int depth)
    {
        if (depth == 0 || _random.Next(5) == 0) return Leaf();
        var (a, fa) = Next(depth - 1);
        switch (_random.Next(14))
        {
            case 0:
            case 1:
            {
                var (b, fb) = Next(depth - 1);
                return (a + b, v => fa(v) + fb(v));
            }
            case 2:
            {
                var (b, fb) = Next(depth - 1);
                return (a - b, v => fa(v) - fb(v));
            }
            case 3:
            case 4:
            {
                var (b, fb) = Next(depth - 1);
                return (a * b, v => fa(v) * fb(v));
            }
            case 5:
            {
                var (b, fb) = Next(depth - 1);
                return (a / (b * b + Scalar.One), v => fa(v) / (fb(v) * fb(v) + 1));
            }
            case 6: return (Scalar.Sin(a), v => Math.Sin(fa(v)));
            case 7: return (Scalar.Cos(a), v => Math.Cos(fa(v)));
            case 8: return (Scalar.Tan(Scalar.Sin(a) / 2), v => Math.Tan(Math.Sin(fa(v)) / 2));
            case 9: return (Scalar.Sqrt(a * a + Scalar.One), v => Math.Sqrt(fa(v) * fa(v) + 1));
            case 10: return (Scalar.Exp(Scalar.Cos(a)) - Scalar.Log(a * a + Scalar.One), v => Math.Exp(Math.Cos(fa(v))) - Math.Log(fa(v) * fa(v) + 1));
            case 11:
            {
                var (b, fb) = Next(depth - 1);
                return (Scalar.Atan2(a, b), v => Math.Atan2(fa(v), fb(v)));
            }
            case 12: return (Scalar.Abs(a), v => Math.Abs(fa(v)));
            default:
            {
                var (b, fb) = Next(depth - 1);
                return (Scalar.Pow(a * a + Scalar.One, Scalar.Sin(b)), v => Math.Pow(fa(v) * fa(v) + 1, Math.Sin(fb(v))));
            }
        }
    }

    private (Scalar, Func<double[], double>) Leaf()
    {
        if (_random.Next(3) == 0)
        {
            var c = new Rational(_random.Next(-5, 6), _random.Next(1, 4));
            var d = c.ToDouble();
            return (Scalar.Constant(c), _ => d);
        }
        var i = _random.Next(VariableNames.Length);
        return (Scalar.Variable(VariableNames[i]), v => v[i]);
    }

    public double[] Point() => [0.3 + _random.NextDouble(), -1.4 + _random.NextDouble(), 0.2 + 2 * _random.NextDouble()];

    public static Func<string, double> Lookup(double[] point) => name => point[Array.IndexOf(VariableNames, name)];
}
