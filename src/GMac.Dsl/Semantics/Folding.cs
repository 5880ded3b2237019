using GMac.Core.Numerics;

namespace GMac.Dsl.Semantics;

/// <summary>Exact evaluation of constant scalar expressions (matrix entries, limits, counts).</summary>
internal static class Folding
{
    private const long MaxBits = 1 << 16;

    public static Rational? TryFold(BoundExpression expression)
    {
        switch (expression)
        {
            case BoundNumber n:
                return n.Value;
            case BoundUnaryOperation { Operator: UnaryOperator.Negate } u:
                return TryFold(u.Operand) is { } v ? -v : null;
            case BoundBinaryOperation b:
            {
                if (TryFold(b.Left) is not { } l || TryFold(b.Right) is not { } r) return null;
                switch (b.Operator)
                {
                    case BinaryOperator.Add: return l + r;
                    case BinaryOperator.Subtract: return l - r;
                    case BinaryOperator.Multiply or BinaryOperator.Gp: return l * r;
                    case BinaryOperator.Divide: return r.IsZero ? null : l / r;
                    case BinaryOperator.Power:
                        if (!r.IsInteger || r.Abs() > 64 || (l.IsZero && r.Sign < 0)) return null;
                        // Nested powers grow exponentially; an entry this large is a mistake.
                        var bits = Math.Max(l.Numerator.GetBitLength(), l.Denominator.GetBitLength()) * (long)r.Abs().Numerator;
                        return bits > MaxBits ? null : l.Pow((int)r.Numerator);
                    default: return null;
                }
            }
            default:
                return null;
        }
    }
}
