namespace GMac.Dsl.Semantics;

/// <summary>
/// A basis blade as written, e.g. <c>e2^e1</c>: the bit mask of its basis vectors
/// in frame order and the sign of the permutation from the written order.
/// </summary>
public readonly record struct BladeReference(int Mask, int Sign)
{
    public int Grade => System.Numerics.BitOperations.PopCount((uint)Mask);
}
