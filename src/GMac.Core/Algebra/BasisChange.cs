using GMac.Core.Numerics;

namespace GMac.Core.Algebra;

/// <summary>
/// Frames derived from a source frame by a basis-change matrix (BCM) C: row i of C holds derived
/// basis vector i in source coordinates, f_i = Σ_j C_ij e_j, so the derived inner-product matrix
/// is C G Cᵀ. A square invertible C gives another frame of the same space; rows picked from the
/// identity give a subspace.
/// </summary>
public static class BasisChange
{
    /// <summary>The inner-product matrix C G Cᵀ of the frame whose basis is the rows of <paramref name="basisChange"/>.</summary>
    public static RationalMatrix DerivedMetric(RationalMatrix sourceMetric, RationalMatrix basisChange)
    {
        if (!sourceMetric.IsSquare || basisChange.Columns != sourceMetric.Rows)
            throw new ArgumentException(
                $"A {basisChange.Rows}x{basisChange.Columns} basis change does not apply to a {sourceMetric.Rows}x{sourceMetric.Columns} inner-product matrix.",
                nameof(basisChange));
        return basisChange * sourceMetric * basisChange.Transpose();
    }

    /// <summary>The basis change that keeps the source basis vectors at <paramref name="indices"/>, in that order.</summary>
    public static RationalMatrix Selection(int sourceDimension, IReadOnlyList<int> indices)
    {
        var c = new Rational[indices.Count, sourceDimension];
        for (var i = 0; i < indices.Count; i++) c[i, indices[i]] = Rational.One;
        return new RationalMatrix(c);
    }

    /// <summary>
    /// An orthogonal basis for the symmetric form <paramref name="metric"/>, by congruence with exact
    /// rational operations: Gram-Schmidt that takes a vector with a non-zero square first and, when
    /// only null vectors remain, mixes a null pair vᵢ + vⱼ/(2 vᵢ·vⱼ), which squares to 1. Each
    /// vector is then scaled to square ±1 when that needs no irrational factor, as the thesis's
    /// orthonormal frames do; the null basis no, ni (no·ni = −1) becomes e = no − ni/2 (e² = 1) and
    /// ē = no + ni/2 (ē² = −1). Null directions orthogonal to everything stay as they are.
    /// Returns the basis change (row i: new vector i in old coordinates) and the diagonal metric.
    /// </summary>
    public static (RationalMatrix BasisChange, RationalMatrix Metric) Orthogonalize(RationalMatrix metric)
    {
        if (!metric.IsSymmetric)
            throw new ArgumentException($"Only a symmetric inner-product matrix can be orthogonalized, not {metric}.", nameof(metric));
        var n = metric.Rows;
        var vectors = new List<Rational[]>();
        for (var i = 0; i < n; i++)
        {
            var v = new Rational[n];
            v[i] = Rational.One;
            vectors.Add(v);
        }

        Rational Dot(Rational[] x, Rational[] y)
        {
            var s = Rational.Zero;
            for (var i = 0; i < n; i++)
            {
                if (x[i].IsZero) continue;
                for (var j = 0; j < n; j++)
                    if (!y[j].IsZero) s += x[i] * metric[i, j] * y[j];
            }
            return s;
        }

        for (var k = 0; k < n; k++)
        {
            var pick = -1;
            for (var i = k; i < n; i++)
                if (!Dot(vectors[i], vectors[i]).IsZero) { pick = i; break; }
            if (pick < 0) pick = MixNullPair(vectors, k, Dot);
            if (pick < 0) break; // the rest is a null block orthogonal to everything
            (vectors[k], vectors[pick]) = (vectors[pick], vectors[k]);
            var vk = vectors[k];
            var square = Dot(vk, vk);
            for (var i = k + 1; i < n; i++)
            {
                var f = Dot(vectors[i], vk) / square;
                if (f.IsZero) continue;
                for (var t = 0; t < n; t++) vectors[i][t] -= f * vk[t];
            }
        }

        var basisChange = new Rational[n, n];
        var diagonal = new Rational[n];
        for (var i = 0; i < n; i++)
        {
            var v = vectors[i];
            var square = Dot(v, v);
            if (!square.IsZero && square.Abs().Reciprocal().TryExactSqrt(out var scale))
            {
                for (var t = 0; t < n; t++) v[t] *= scale;
                square = square.Sign > 0 ? Rational.One : Rational.MinusOne;
            }
            diagonal[i] = square;
            for (var t = 0; t < n; t++) basisChange[i, t] = v[t];
        }
        return (new RationalMatrix(basisChange), RationalMatrix.Diagonal(diagonal));
    }

    /// <summary>
    /// Among vectors from <paramref name="from"/> on, all null, finds a pair with vᵢ·vⱼ = p ≠ 0 and
    /// replaces vᵢ by vᵢ + vⱼ/(2p), whose square 2·p/(2p) is 1. Returns i, or −1 when there is none.
    /// </summary>
    private static int MixNullPair(List<Rational[]> vectors, int from, Func<Rational[], Rational[], Rational> dot)
    {
        var n = vectors.Count;
        for (var i = from; i < n; i++)
        for (var j = i + 1; j < n; j++)
        {
            var p = dot(vectors[i], vectors[j]);
            if (p.IsZero) continue;
            var c = Rational.One / (2 * p);
            for (var t = 0; t < n; t++) vectors[i][t] += c * vectors[j][t];
            return i;
        }
        return -1;
    }
}
