using GMac.Core.Algebra;

namespace GMac.Core.Tests.Algebra;

/// <summary>Seeded random multivectors and tolerant comparisons for numeric identity tests.</summary>
internal sealed class RandomMultivectors(int seed)
{
    private readonly Random _random = new(seed);

    public double Number() => _random.NextDouble() * 2 - 1;

    public Multivector<double> General(Frame frame) =>
        Multivector<double>.FromTerms(frame, Enumerable.Range(0, frame.BladeCount).Select(id => (new BasisBlade(id), Number())));

    public Multivector<double> OfGrade(Frame frame, int k) =>
        Multivector<double>.FromTerms(frame, frame.BladesOfGrade(k).Select(b => (b, Number())));

    public Multivector<double> Vector(Frame frame) => OfGrade(frame, 1);

    /// <summary>A vector whose square is safely away from zero.</summary>
    public Multivector<double> NonNullVector(Frame frame)
    {
        while (true)
        {
            var v = Vector(frame);
            if (Math.Abs(v.Gp(v).ScalarPart) > 0.2) return v;
        }
    }

    /// <summary>A product of k non-null vectors.</summary>
    public Multivector<double> Versor(Frame frame, int k)
    {
        var v = Multivector<double>.FromScalar(frame, 1);
        for (var i = 0; i < k; i++) v = v.Gp(NonNullVector(frame));
        return v;
    }

    /// <summary>An outer product of k random vectors: a blade.</summary>
    public Multivector<double> Blade(Frame frame, int k)
    {
        var b = Multivector<double>.FromScalar(frame, 1);
        for (var i = 0; i < k; i++) b = b.Op(Vector(frame));
        return b;
    }
}
