using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

/// <summary>
/// The numeric products (per-thread accumulators, per-frame sign tables) against a term-by-term
/// reference built only from <see cref="Frame.BladeProduct"/>, the exact rational blade products,
/// and against identities that hold whatever the implementation.
/// </summary>
public class Multivector_DirectProducts
{
    /// <summary>Σ over term pairs of the exact blade products, summed per blade in a dictionary.</summary>
    private static Dictionary<int, double> Reference(ProductKind kind, Multivector<double> a, Multivector<double> b)
    {
        var sums = new Dictionary<int, double>();
        foreach (var (ba, ca) in a.Terms)
        foreach (var (bb, cb) in b.Terms)
        foreach (var term in a.Frame.BladeProduct(kind, ba, bb))
            sums[term.Blade] = sums.GetValueOrDefault(term.Blade) + term.Coefficient.ToDouble() * ca * cb;
        return sums;
    }

    private static void AssertMatches(Dictionary<int, double> expected, Multivector<double> actual)
    {
        var scale = Math.Max(1, expected.Values.Select(Math.Abs).DefaultIfEmpty(0).Max());
        for (var id = 0; id < actual.Frame.BladeCount; id++)
        {
            var e = expected.GetValueOrDefault(id);
            var got = actual[new BasisBlade(id)];
            if (Math.Abs(e - got) > 1e-9 * scale)
                Assert.Fail($"{actual.Frame.Name}, blade {actual.Frame.BladeName(new BasisBlade(id))}: expected {e}, got {got}");
        }
        Assert.True(actual.Terms.All(t => t.Coefficient != 0), "exact zeros are dropped");
    }

    public static IEnumerable<object[]> FramesAndKinds() =>
        from f in TestFrames.All().Select(o => (string)o[0]).Append("cl63")
        from k in Enum.GetValues<ProductKind>()
        select new object[] { f, k };

    /// <summary>Cl(6,3): nine dimensions, past the sign tables, so the bitwise signs are checked too.</summary>
    private static readonly Frame Cl63 = Frame.FromSignature("cl63", 6, 3);

    private static Frame ByName(string name) => name == "cl63" ? Cl63 : TestFrames.ByName(name);

    [Theory]
    [MemberData(nameof(FramesAndKinds))]
    public void Every_product_matches_a_term_by_term_reference(string frameName, ProductKind kind)
    {
        var frame = ByName(frameName);
        var r = new RandomMultivectors(11);
        var operands = frame.Dimension > 6
            ? new[] { (r.Blade(frame, 2), r.Vector(frame)), (r.OfGrade(frame, 3), r.Blade(frame, 2)) }
            : new[] { (r.General(frame), r.General(frame)), (r.Vector(frame), r.Blade(frame, 2)), (r.Versor(frame, 2), r.General(frame)) };
        foreach (var (a, b) in operands) AssertMatches(Reference(kind, a, b), a.Product(kind, b));
    }

    [Theory]
    [MemberData(nameof(FramesAndKinds))]
    public void Every_product_distributes_over_addition(string frameName, ProductKind kind)
    {
        var frame = ByName(frameName);
        if (frame.Dimension > 6) return; // general multivectors of 512 blades: covered by the reference test
        var r = new RandomMultivectors(12);
        for (var i = 0; i < 5; i++)
        {
            var (a, b, c) = (r.General(frame), r.General(frame), r.General(frame));
            MultivectorAssert.Close(a.Product(kind, b) + a.Product(kind, c), a.Product(kind, b + c));
            MultivectorAssert.Close(a.Product(kind, c) + b.Product(kind, c), (a + b).Product(kind, c));
            MultivectorAssert.Close(a.Product(kind, b) * 3, (3.0 * a).Product(kind, b));
        }
    }

    [Fact]
    public void Products_on_many_threads_agree_with_products_on_one()
    {
        var frame = TestFrames.Conformal;
        var r = new RandomMultivectors(13);
        var pairs = Enumerable.Range(0, 64).Select(_ => (r.General(frame), r.Vector(frame))).ToArray();
        var sequential = pairs.Select(p => p.Item1.Gp(p.Item2).Op(p.Item1)).ToArray();
        var parallel = new Multivector<double>[pairs.Length];
        Parallel.For(0, pairs.Length, i => parallel[i] = pairs[i].Item1.Gp(pairs[i].Item2).Op(pairs[i].Item1));
        for (var i = 0; i < pairs.Length; i++) Assert.True(sequential[i].Equals(parallel[i]));
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Cancelling_terms_leave_no_zero_coefficients(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var r = new RandomMultivectors(14);
        var v = r.Vector(frame);
        var a = r.General(frame);
        Assert.True(v.Op(v).IsZero);
        Assert.True((a - a).IsZero);
        MultivectorAssert.Close(Multivector<double>.Zero(frame), a.Op(v).Op(v)); // zero up to rounding: the two orders of a product differ in the last bits
        var b = a.Gp(v);
        Assert.True((b - a.Gp(v)).IsZero);
    }

    [Theory]
    [MemberData(nameof(TestFrames.All), MemberType = typeof(TestFrames))]
    public void Involutions_and_grade_parts_follow_the_grade_signs(string frameName)
    {
        var frame = TestFrames.ByName(frameName);
        var a = new RandomMultivectors(15).General(frame);
        foreach (var (blade, c) in a.Terms)
        {
            var k = blade.Grade;
            Assert.Equal(c * BasisBlade.ReverseSign(k), a.Reverse()[blade]);
            Assert.Equal(c * BasisBlade.GradeInvolutionSign(k), a.GradeInvolution()[blade]);
            Assert.Equal(c * BasisBlade.CliffordConjugateSign(k), a.CliffordConjugate()[blade]);
            Assert.Equal(c, a.Grade(k)[blade]);
        }
        var sum = Multivector<double>.Zero(frame);
        foreach (var k in a.Grades) sum += a.Grade(k);
        Assert.True(sum.Equals(a));
        Assert.Equal(Enumerable.Range(0, frame.Dimension + 1).ToArray(), a.Grades);
    }

    [Fact]
    public void Conformal_points_meet_in_the_squared_distance()
    {
        // X·Y = −½|x − y|² for normalized points no + x + ½x² ni (independent of the product code: plain arithmetic on the right).
        var frame = TestFrames.Conformal;
        var random = new Random(16);
        for (var i = 0; i < 20; i++)
        {
            var (x, y) = (Enumerable.Range(0, 3).Select(_ => random.NextDouble() * 4 - 2).ToArray(), Enumerable.Range(0, 3).Select(_ => random.NextDouble() * 4 - 2).ToArray());
            Multivector<double> Point(double[] p) => Multivector<double>.Vector(frame, 1, p[0], p[1], p[2], p.Sum(c => c * c) / 2);
            var squared = x.Zip(y, (a, b) => (a - b) * (a - b)).Sum();
            MultivectorAssert.Close(-squared / 2, Point(x).Lcp(Point(y)).ScalarPart);
            MultivectorAssert.Close(0, Point(x).Gp(Point(x)).ScalarPart);
        }
    }
}
