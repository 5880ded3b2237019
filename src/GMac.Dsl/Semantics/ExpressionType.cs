namespace GMac.Dsl.Semantics;

/// <summary>
/// Static type of an expression: a plain scalar (no frame) or a multivector of a
/// frame, with a conservative set of the grades it may hold (bit k = grade k).
/// </summary>
public readonly record struct ExpressionType(FrameSymbol? Frame, int GradeMask)
{
    public static readonly ExpressionType Scalar = new(null, 1);
    public bool IsScalar => Frame is null;
}
