using System.Numerics;

namespace GMac.Core.Algebra;

public sealed partial class Multivector<T>
{
    /// <summary>Any bilinear product of Table 3-2, term by term through the frame's product table.</summary>
    public Multivector<T> Product(ProductKind kind, Multivector<T> other)
    {
        RequireSameFrame(this, other, "multiply");
        if (IsZero || other.IsZero) return Zero(Frame);
        var table = ProductTable<T>.For(Frame, kind);
        var acc = new Accumulator(Frame);
        var bIds = other._ids;
        var bCs = other._coefficients;
        for (var i = 0; i < _ids.Length; i++)
        {
            var a = _ids[i];
            var ca = _coefficients[i];
            for (var j = 0; j < bIds.Length; j++)
            {
                var entry = table.Get(a, bIds[j]);
                if (entry.Blades.Length == 0) continue;
                var ab = ca * bCs[j];
                for (var k = 0; k < entry.Blades.Length; k++)
                    acc.Add(entry.Blades[k], entry.IsOne[k] ? ab : entry.Coefficients[k] * ab);
            }
        }
        return acc.ToMultivector();
    }

    public Multivector<T> Gp(Multivector<T> b) => Product(ProductKind.Geometric, b);
    public Multivector<T> Op(Multivector<T> b) => Product(ProductKind.Outer, b);
    public Multivector<T> Lcp(Multivector<T> b) => Product(ProductKind.LeftContraction, b);
    public Multivector<T> Rcp(Multivector<T> b) => Product(ProductKind.RightContraction, b);
    public Multivector<T> Fdp(Multivector<T> b) => Product(ProductKind.FatDot, b);
    public Multivector<T> Hip(Multivector<T> b) => Product(ProductKind.HestenesInner, b);
    public Multivector<T> Cp(Multivector<T> b) => Product(ProductKind.Commutator, b);
    public Multivector<T> Acp(Multivector<T> b) => Product(ProductKind.AntiCommutator, b);

    /// <summary>The scalar product A * B = ⟨AB⟩₀, as a scalar multivector.</summary>
    public Multivector<T> Sp(Multivector<T> b) => Product(ProductKind.Scalar, b);

    /// <summary>The scalar product as a plain scalar.</summary>
    public T ScalarProduct(Multivector<T> b) => Sp(b).ScalarPart;
}
