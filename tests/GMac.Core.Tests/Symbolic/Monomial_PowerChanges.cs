using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

/// <summary>
/// Setting one atom's power in place (and reading it) against building the monomial again from
/// its factors through the general, sorting constructor.
/// </summary>
public class Monomial_PowerChanges
{
    private static readonly Atom[] Atoms = new[] { "p", "q", "r", "s", "t", "u" }.Select(n => Scalar.Variable(n).Terms[0].Monomial.Factors[0].Atom).ToArray();

    [Fact]
    public void Setting_a_power_matches_rebuilding_the_monomial_from_its_factors()
    {
        var random = new Random(11);
        for (var trial = 0; trial < 500; trial++)
        {
            var factors = Atoms.Where(_ => random.Next(2) == 0).Select(a => new Factor(a, random.Next(1, 4) * (random.Next(2) == 0 ? 1 : -1))).ToList();
            var m = Monomial.Create(factors.OrderBy(_ => random.Next()));
            var atom = Atoms[random.Next(Atoms.Length)];
            var power = random.Next(-3, 4);

            var expected = Monomial.Create(factors.Where(f => !ReferenceEquals(f.Atom, atom)).Append(new Factor(atom, power)));
            Assert.Same(expected, Monomial.WithPower(m, atom, power));
            Assert.Equal(factors.FirstOrDefault(f => ReferenceEquals(f.Atom, atom)).Power, m.PowerOf(atom));
            Assert.Equal(power, Monomial.WithPower(m, atom, power).PowerOf(atom));
        }
    }

    [Fact]
    public void Setting_a_power_of_zero_removes_the_atom_and_an_absent_atom_is_inserted_in_order()
    {
        Monomial Of(params Atom[] atoms) => Monomial.Create(atoms.Select(a => new Factor(a, 1)));
        var (p, q, r) = (Atoms[0], Atoms[1], Atoms[2]);
        Assert.Same(Of(p, r), Monomial.WithPower(Of(p, q, r), q, 0));
        Assert.Same(Of(p, q, r), Monomial.WithPower(Of(p, r), q, 1));
        Assert.Same(Of(p, q, r), Monomial.WithPower(Of(q, r), p, 1));
        Assert.Same(Of(p, q, r), Monomial.WithPower(Of(p, q), r, 1));
        Assert.Same(Monomial.One, Monomial.WithPower(Of(p), p, 0));
        Assert.Same(Of(p), Monomial.WithPower(Monomial.One, p, 1));
    }
}
