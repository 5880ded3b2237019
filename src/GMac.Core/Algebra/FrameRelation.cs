using System.Numerics;
using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// Two frames of one vector space: a derived frame whose basis vectors are combinations of a
/// base frame's, f_i = Σ_j C_ij e_j (C the basis-change matrix), so that its metric is C G Cᵀ.
/// Multivectors move between them through outermorphisms, which preserve every product.
/// </summary>
public sealed class FrameRelation
{
    /// <summary>The frame built from the basis-change matrix.</summary>
    public Frame Derived { get; }

    /// <summary>The frame it was built on.</summary>
    public Frame Base { get; }

    /// <summary>The basis-change matrix C (row i: f_i in base coordinates).</summary>
    public RationalMatrix BasisChange { get; }

    private readonly RationalMatrix _inverse;

    private FrameRelation(Frame derived, Frame baseFrame, RationalMatrix basisChange, RationalMatrix inverse)
    {
        Derived = derived;
        Base = baseFrame;
        BasisChange = basisChange;
        _inverse = inverse;
    }

    /// <summary>A frame whose basis vectors are the rows of the basis-change matrix over the base frame.</summary>
    public static FrameRelation Derive(Frame baseFrame, string name, IReadOnlyList<string> basisVectorNames, RationalMatrix basisChange)
    {
        var n = baseFrame.Dimension;
        if (basisChange.Rows != n || basisChange.Columns != n)
            throw new AlgebraException(name,
                $"the basis-change matrix over '{baseFrame.Name}' must be {n}x{n}, not {basisChange.Rows}x{basisChange.Columns}.");
        if (!basisChange.TryInverse(out var inverse))
            throw new AlgebraException(name, $"the basis-change matrix {basisChange} is singular, so it does not define a basis.");
        var metric = basisChange * baseFrame.Metric.Matrix * basisChange.Transpose();
        var derived = new Frame(name, basisVectorNames, Metric.FromMatrix(metric, name));
        return new FrameRelation(derived, baseFrame, basisChange, inverse);
    }

    /// <summary>
    /// An orthogonal frame of the same space: the metric is diagonalized by congruence with exact
    /// rational row operations (no square roots), so the derived frame's metric is diagonal.
    /// </summary>
    public static FrameRelation Orthogonalize(Frame frame, string name, IReadOnlyList<string>? basisVectorNames = null)
    {
        var n = frame.Dimension;
        var g = frame.Metric.Matrix.ToArray();
        var c = RationalMatrix.Identity(n).ToArray();
        for (var k = 0; k < n; k++)
        {
            if (g[k, k].IsZero)
            {
                var j = Enumerable.Range(k + 1, n - k - 1).FirstOrDefault(j => !g[j, j].IsZero, -1);
                if (j >= 0)
                {
                    SwapBasisVectors(g, c, k, j);
                }
                else
                {
                    j = Enumerable.Range(k + 1, n - k - 1).FirstOrDefault(j => !g[k, j].IsZero, -1);
                    if (j < 0) continue; // a null direction orthogonal to everything left: already diagonal
                    AddBasisVector(g, c, k, j, Rational.One); // f_k = e_k + e_j squares to 2 g_kj ≠ 0
                }
            }
            for (var i = k + 1; i < n; i++)
                if (!g[i, k].IsZero) AddBasisVector(g, c, i, k, -(g[i, k] / g[k, k]));
        }
        var names = basisVectorNames ?? Enumerable.Range(1, n).Select(i => $"f{i}").ToArray();
        return Derive(frame, name, names, new RationalMatrix(c));
    }

    /// <summary>f_target += factor · f_source, as a congruence on the metric and a row operation on C.</summary>
    private static void AddBasisVector(Rational[,] g, Rational[,] c, int target, int source, Rational factor)
    {
        var n = g.GetLength(0);
        for (var col = 0; col < n; col++) g[target, col] += factor * g[source, col];
        for (var row = 0; row < n; row++) g[row, target] += factor * g[row, source];
        for (var col = 0; col < n; col++) c[target, col] += factor * c[source, col];
    }

    private static void SwapBasisVectors(Rational[,] g, Rational[,] c, int a, int b)
    {
        var n = g.GetLength(0);
        for (var col = 0; col < n; col++) { (g[a, col], g[b, col]) = (g[b, col], g[a, col]); (c[a, col], c[b, col]) = (c[b, col], c[a, col]); }
        for (var row = 0; row < n; row++) (g[row, a], g[row, b]) = (g[row, b], g[row, a]);
    }

    /// <summary>Carries multivectors of the derived frame into the base frame.</summary>
    public Outermorphism<T> ToBase<T>()
        where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T> =>
        Outermorphism<T>.FromMatrix(Derived, Base, BasisChange.Transpose());

    /// <summary>Carries multivectors of the base frame into the derived frame.</summary>
    public Outermorphism<T> ToDerived<T>()
        where T : INumberBase<T>, IRootFunctions<T>, ITrigonometricFunctions<T>, IHyperbolicFunctions<T> =>
        Outermorphism<T>.FromMatrix(Base, Derived, _inverse.Transpose());
}
