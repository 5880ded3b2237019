using System.Collections.Concurrent;
using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// A linear map of vectors extended to all multivectors by L[a ∧ b] = L[a] ∧ L[b] (3.50–3.51).
/// Column j of the matrix holds the image of basis vector j, in the codomain's coordinates.
/// </summary>
public sealed class Outermorphism<T>
    where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T>
{
    private readonly Multivector<T>[] _vectorImages;
    private readonly ConcurrentDictionary<int, Multivector<T>> _bladeImages = new();

    public Frame Domain { get; }
    public Frame Codomain { get; }

    public Outermorphism(Frame domain, Frame codomain, T[,] matrix)
    {
        if (matrix.GetLength(0) != codomain.Dimension || matrix.GetLength(1) != domain.Dimension)
            throw new AlgebraException(domain.Name,
                $"a linear map from '{domain.Name}' to '{codomain.Name}' needs a {codomain.Dimension}x{domain.Dimension} matrix, not {matrix.GetLength(0)}x{matrix.GetLength(1)}.");
        Domain = domain;
        Codomain = codomain;
        _vectorImages = new Multivector<T>[domain.Dimension];
        for (var j = 0; j < domain.Dimension; j++)
        {
            var column = new T[codomain.Dimension];
            for (var i = 0; i < codomain.Dimension; i++) column[i] = matrix[i, j];
            _vectorImages[j] = Multivector<T>.Vector(codomain, column);
        }
    }

    public static Outermorphism<T> FromMatrix(Frame domain, Frame codomain, RationalMatrix matrix)
    {
        var m = new T[matrix.Rows, matrix.Columns];
        for (var i = 0; i < matrix.Rows; i++)
        for (var j = 0; j < matrix.Columns; j++)
            m[i, j] = ProductTable<T>.Convert(matrix[i, j]);
        return new Outermorphism<T>(domain, codomain, m);
    }

    /// <summary>The image of a basis blade, built once from the images of its vectors.</summary>
    public Multivector<T> Image(BasisBlade blade) =>
        _bladeImages.GetOrAdd(blade.Id, id =>
        {
            var image = Multivector<T>.FromScalar(Codomain, T.One);
            foreach (var i in new BasisBlade(id).BasisVectorIndices()) image = image.Op(_vectorImages[i]);
            return image;
        });

    public Multivector<T> Apply(Multivector<T> a)
    {
        if (!ReferenceEquals(a.Frame, Domain))
            throw new AlgebraException(Domain.Name, $"this map acts on frame '{Domain.Name}', not on '{a.Frame.Name}'.");
        var result = Multivector<T>.Zero(Codomain);
        foreach (var (blade, c) in a.Terms) result += Image(blade).Scale(c);
        return result;
    }
}
