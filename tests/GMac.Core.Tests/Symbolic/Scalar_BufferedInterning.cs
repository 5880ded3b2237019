using GMac.Core.Numerics;
using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// Sums, differences, scaled copies and single terms are built in a reused buffer and looked up
/// from there. Built any other way (from a shuffled term list), the same value must be the same
/// object with exactly its own terms, whatever larger or smaller scalar used the buffer before.
/// </summary>
public class Scalar_BufferedInterning
{
    private static readonly Scalar[] Atoms = new[] { "a", "b", "c", "d", "e" }.Select(Scalar.Variable).ToArray();

    private static Scalar RandomPolynomial(Random random, int maxTerms)
    {
        var terms = new List<Term>();
        for (var i = random.Next(1, maxTerms + 1); i > 0; i--)
        {
            var monomial = Monomial.One;
            for (var f = random.Next(0, 4); f > 0; f--) monomial *= Atoms[random.Next(Atoms.Length)].Terms[0].Monomial;
            terms.Add(new Term(new Rational(random.Next(-9, 10), random.Next(1, 4)), monomial));
        }
        return Scalar.FromTerms(terms);
    }

    /// <summary>The value rebuilt from its terms in a random order, through the list path that uses no buffer.</summary>
    private static Scalar Rebuilt(Scalar s, Random random) => Scalar.FromTerms(s.Terms.OrderBy(_ => random.Next()).ToList());

    [Fact]
    public void Sums_differences_and_scaled_copies_are_the_objects_built_from_their_terms()
    {
        var random = new Random(5);
        for (var trial = 0; trial < 400; trial++)
        {
            // alternate large and small operands so a short result follows a long one in the buffer
            var x = RandomPolynomial(random, trial % 2 == 0 ? 30 : 2);
            var y = RandomPolynomial(random, trial % 3 == 0 ? 30 : 3);
            var factor = new Rational(random.Next(-5, 6), random.Next(1, 5));

            var sum = x + y;
            var difference = x - y;
            var scaled = Scalar.Scale(x, factor);
            var combined = new Dictionary<Monomial, Rational>();
            foreach (var t in x.Terms) combined[t.Monomial] = t.Coefficient;
            foreach (var t in y.Terms) combined[t.Monomial] = combined.GetValueOrDefault(t.Monomial) + t.Coefficient;
            var expected = Scalar.FromTerms(combined.Where(kv => !kv.Value.IsZero).Select(kv => new Term(kv.Value, kv.Key)).ToList());

            Assert.Same(expected, sum);
            Assert.Equal(combined.Count(kv => !kv.Value.IsZero), sum.Terms.Count);
            Assert.Same(Rebuilt(sum, random), sum);
            Assert.Same(Rebuilt(difference, random), difference);
            Assert.Same(Scalar.Zero, difference - x + y);
            Assert.Same(Rebuilt(scaled, random), scaled);
            Assert.Equal(factor.IsZero ? 0 : x.Terms.Count, scaled.Terms.Count);
        }
    }

    [Fact]
    public void A_single_term_is_the_object_of_its_one_term_list()
    {
        var random = new Random(6);
        for (var trial = 0; trial < 100; trial++)
        {
            var big = RandomPolynomial(random, 40);
            _ = big + big; // leaves a long sum in the buffer
            var monomial = Atoms[random.Next(Atoms.Length)].Terms[0].Monomial * Atoms[random.Next(Atoms.Length)].Terms[0].Monomial;
            var term = new Term(new Rational(random.Next(1, 9) * (random.Next(2) == 0 ? 1 : -1), random.Next(1, 4)), monomial);
            var single = Scalar.FromTerm(term.Coefficient, term.Monomial);
            Assert.Same(Scalar.FromTerms([term]), single);
            Assert.Single(single.Terms);
            Assert.Same(single, Scalar.FromTerm(Rational.One, term.Monomial) * Scalar.Constant(term.Coefficient));
        }
    }
}
