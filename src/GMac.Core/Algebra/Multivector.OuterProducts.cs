namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    /// <summary>
    /// v1 ∧ v2 ∧ … ∧ vk for vectors, evaluated to need few operations. The outer product does not
    /// change when a multiple of one factor is added to another, so when every vector has the same
    /// known, non-zero coefficient on some basis vector (normalized conformal points all have
    /// no-coefficient 1), that component is cancelled for free: v1 ∧ (v2 − v1) ∧ … ∧ (vk − v1).
    /// The differences span a smaller subspace, and their product is taken before v1 joins.
    /// <paramref name="name"/> may name intermediate results (e.g. a temporary recorder).
    /// </summary>
    public static Multivector<T> OuterProductOfVectors(IReadOnlyList<Multivector<T>> vectors, Func<Multivector<T>, Multivector<T>>? name = null)
    {
        if (vectors.Count == 0) throw new ArgumentException("An outer product needs at least one factor.", nameof(vectors));
        var frame = vectors[0].Frame;
        foreach (var v in vectors) RequireSameFrame(vectors[0], v, "take the outer product of");
        name ??= m => m;
        if (vectors.Count == 1) return vectors[0];

        var pivot = SharedConstantBlade(vectors);
        if (pivot is null)
        {
            var product = vectors[0];
            for (var i = 1; i < vectors.Count; i++) product = name(product.Op(vectors[i]));
            return product;
        }

        var rest = Multivector<T>.FromScalar(frame, T.One);
        for (var i = vectors.Count - 1; i >= 1; i--)
            rest = name(name(vectors[i] - vectors[0]).Op(rest));
        return name(vectors[0].Op(rest));
    }

    /// <summary>A basis vector on which every factor has the same known non-zero coefficient.</summary>
    private static BasisBlade? SharedConstantBlade(IReadOnlyList<Multivector<T>> vectors)
    {
        if (vectors.Any(v => v.Grades.Any(g => g != 1))) return null;
        foreach (var (blade, c) in vectors[0].Terms)
        {
            if (T.IsZero(c) || !T.IsRealNumber(c)) continue;
            if (vectors.All(v => v[blade].Equals(c))) return blade;
        }
        return null;
    }
}
