using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>
/// signature {name: square, …} chooses the null or negative vectors by name; signature (p, q, r)
/// counts in basis order and warns where that contradicts an e0 written first.
/// </summary>
public sealed class Binder_NamedSignatures
{
    [Fact]
    public void Named_signature_puts_each_square_on_its_named_vector()
    {
        var project = SingleFileProject.Bind("define frame pga as basis: {e0, e1, e2, e3} signature {e0: 0, e1: +1, e3: -1, e2: 1} end frame");
        Assert.Empty(project.Diagnostics);
        var f = project.Model.Frames["pga"];
        Assert.Equal([0, 1, 1, -1], Enumerable.Range(0, 4).Select(i => (int)f.InnerProductMatrix[i, i].Numerator));
    }

    [Fact]
    public void Named_signature_with_an_unknown_or_repeated_or_missing_name_is_an_error()
    {
        var unknown = MarkedSource.AssertSingle("define frame a as basis: {x, y} signature {x: 1, «z»: 0} end frame", "GMAC0101");
        Assert.Contains("'z'", unknown.Message);
        var twice = MarkedSource.AssertSingle("define frame a as basis: {x, y} signature {x: 1, «x: 0»} end frame", "GMAC0124");
        Assert.Equal("signature gives basis vector 'x' twice", twice.Message);
        var missing = MarkedSource.AssertSingle("define frame a as basis: {x, y} «signature {x: 1}» end frame", "GMAC0124");
        Assert.Equal("signature does not give the square of 'y'", missing.Message);
    }

    [Fact]
    public void Counted_signature_that_makes_a_later_vector_null_instead_of_e0_warns_with_the_named_form()
    {
        var d = MarkedSource.AssertSingle("define frame pga as basis: {e0, e1, e2, e3} «signature (3, 0, 1)» end frame", "GMAC0204");
        Assert.Equal("signature (3, 0, 1) counts +1, -1, 0 in basis order: it makes e0 positive and e3 null; "
            + "to choose by name write e.g. signature {e0: 0, e1: +1, e2: +1, e3: +1}", d.Message);
    }

    [Theory]
    [InlineData("basis: {e1, e2, e3, e0} signature (3, 0, 1)")]  // e0 last: null as written
    [InlineData("basis: {e0, e1, e2, e3} signature (1, 3)")]     // spacetime, e0 timelike
    [InlineData("basis: {e0, e1, e2, e3} signature (4, 0, 0)")]
    [InlineData("basis: {x, y, z, w} signature (3, 0, 1)")]          // no e0 to contradict
    public void Counted_signature_that_agrees_with_the_names_does_not_warn(string body)
    {
        var project = SingleFileProject.Bind($"define frame f as {body} end frame");
        Assert.Empty(project.Diagnostics);
    }
}
