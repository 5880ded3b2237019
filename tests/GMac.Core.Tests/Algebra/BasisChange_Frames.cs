using GMac.Core.Algebra;
using GMac.Core.Numerics;

namespace GMac.Core.Tests.Algebra;

/// <summary>Derived frames: orthogonalization by congruence, subspaces, and products carried between frames.</summary>
public class BasisChange_Frames
{
    /// <summary>
    /// Signatures as diagonal blocks: +a and −a on the diagonal (a a small integer, so some need no
    /// rescaling and some cannot be rescaled to ±1), 0 for degenerate directions, and the
    /// hyperbolic block {{0, a}, {a, 0}} (one positive and one negative direction, no non-null basis
    /// vector), which forces the null-pair step.
    /// </summary>
    private static (RationalMatrix Matrix, int Positive, int Negative, int Null) RandomSignature(Random random, int n)
    {
        var s = new Rational[n, n];
        var (positive, negative, nulls) = (0, 0, 0);
        var i = 0;
        while (i < n)
        {
            var a = random.Next(1, 5);
            switch (random.Next(i + 1 < n ? 4 : 3))
            {
                case 0: s[i, i] = a; positive++; break;
                case 1: s[i, i] = -a; negative++; break;
                case 2: s[i, i] = 0; nulls++; break;
                default:
                    s[i, i + 1] = s[i + 1, i] = a;
                    positive++;
                    negative++;
                    i++;
                    break;
            }
            i++;
        }
        return (new RationalMatrix(s), positive, negative, nulls);
    }

    private static RationalMatrix RandomInvertible(Random random, int n)
    {
        while (true)
        {
            var p = new Rational[n, n];
            for (var i = 0; i < n; i++)
            for (var j = 0; j < n; j++)
                p[i, j] = random.Next(-2, 3);
            var m = new RationalMatrix(p);
            if (!m.Determinant().IsZero) return m;
        }
    }

    private static bool IsRationalSquare(Rational r) => r.TryExactSqrt(out _);

    [Fact]
    public void Orthogonalizing_random_integer_metrics_is_an_exact_congruence_with_the_same_signature()
    {
        var random = new Random(31);
        for (var trial = 0; trial < 200; trial++)
        {
            var n = random.Next(1, 7);
            var (s, positive, negative, nulls) = RandomSignature(random, n);
            var p = RandomInvertible(random, n);
            var g = p.Transpose() * s * p; // symmetric, integer, with the signature of s (Sylvester)

            var (c, d) = BasisChange.Orthogonalize(g);

            Assert.True(d.IsDiagonal, $"{g} gave {d}");
            Assert.Equal(d, c * g * c.Transpose());
            Assert.True(c.TryInverse(out var back), $"{g} gave a singular basis change {c}");
            Assert.Equal(g, back * d * back.Transpose()); // the metric comes back exactly
            var diagonal = Enumerable.Range(0, n).Select(i => d[i, i]).ToList();
            Assert.Equal(positive, diagonal.Count(x => x.Sign > 0));
            Assert.Equal(negative, diagonal.Count(x => x.Sign < 0));
            Assert.Equal(nulls, diagonal.Count(x => x.IsZero));
            // A square that has a rational square root is scaled to ±1.
            Assert.All(diagonal.Where(x => !x.IsZero && IsRationalSquare(x.Abs())), x => Assert.Equal(Rational.One, x.Abs()));
        }
    }

    [Fact]
    public void Orthogonalizing_the_conformal_null_basis_gives_e_and_ebar()
    {
        // Thesis (3.68): no·ni = −1; e = no − ni/2 squares to 1 and ē = no + ni/2 to −1.
        var g = TestFrames.Conformal.Metric.Matrix;
        var (c, d) = BasisChange.Orthogonalize(g);
        var half = new Rational(1, 2);
        Assert.Equal(RationalMatrix.Diagonal([1, 1, 1, 1, -1]), d);
        Assert.Equal(RationalMatrix.FromRows([
            [0, 1, 0, 0, 0],
            [0, 0, 1, 0, 0],
            [0, 0, 0, 1, 0],
            [1, 0, 0, 0, -half],
            [1, 0, 0, 0, half],
        ]), c);
    }

    [Fact]
    public void A_zero_metric_is_left_as_it_is()
    {
        var (c, d) = BasisChange.Orthogonalize(RationalMatrix.Diagonal([0, 0, 0]));
        Assert.Equal(RationalMatrix.Identity(3), c);
        Assert.Equal(RationalMatrix.Diagonal([0, 0, 0]), d);
    }

    [Fact]
    public void A_non_symmetric_metric_is_refused()
    {
        Assert.Throws<ArgumentException>(() => BasisChange.Orthogonalize(RationalMatrix.FromRows([[1, 2], [3, 1]])));
    }

    [Fact]
    public void Selection_takes_the_sub_block_of_the_metric_in_the_order_given()
    {
        var g = TestFrames.Conformal.Metric.Matrix; // no, e1, e2, e3, ni
        var c = BasisChange.Selection(5, [4, 0]);
        Assert.Equal(RationalMatrix.FromRows([[0, -1], [-1, 0]]), BasisChange.DerivedMetric(g, c));
    }

    [Fact]
    public void A_basis_change_of_the_wrong_width_is_refused()
    {
        Assert.Throws<ArgumentException>(() => BasisChange.DerivedMetric(RationalMatrix.Identity(3), RationalMatrix.Identity(2)));
    }

    [Theory]
    [InlineData("cga5d")]
    [InlineData("skew")]
    [InlineData("pga")]
    public void Products_computed_in_the_orthogonal_frame_agree_with_the_source_frame(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var (c, d) = BasisChange.Orthogonalize(frame.Metric.Matrix);
        var orthogonal = new Frame(frame.Name + "_o", Enumerable.Range(1, frame.Dimension).Select(i => $"f{i}").ToArray(), Metric.FromMatrix(d));
        // Coordinates transform with the inverse transpose of the basis change.
        var toOrthogonal = Outermorphism<double>.FromMatrix(frame, orthogonal, c.Inverse().Transpose());
        var fromOrthogonal = Outermorphism<double>.FromMatrix(orthogonal, frame, c.Transpose());
        var r = new RandomMultivectors(17);
        foreach (var kind in Enum.GetValues<ProductKind>())
        {
            var (a, b) = (r.General(frame), r.General(frame));
            var viaOrthogonal = fromOrthogonal.Apply(toOrthogonal.Apply(a).Product(kind, toOrthogonal.Apply(b)));
            MultivectorAssert.Close(a.Product(kind, b), viaOrthogonal, 1e-8);
        }
    }
}
