using GMac.Core.Numerics;
using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>Frame and transform matrices against hand-computed linear algebra.</summary>
public sealed class Binder_Frames
{
    private static SemanticModel Bind(string text)
    {
        var project = SingleFileProject.Bind(text);
        Assert.True(project.Diagnostics.All(d => !d.IsError), string.Join("\n", project.Diagnostics));
        return project.Model;
    }

    [Fact]
    public void Signature_frame_puts_positive_negative_then_null_on_the_diagonal()
    {
        var f = Bind("define frame g as basis: {a, b, c, d} signature (2, 1, 1) end frame").Frames["g"];
        Assert.Equal([1, 1, -1, 0], Enumerable.Range(0, 4).Select(i => (int)f.InnerProductMatrix[i, i].Numerator));
    }

    [Fact]
    public void Transformed_frame_has_ipm_b_g_bt()
    {
        // Rows of B are the new basis vectors: s = x + y, t = 2y, so s·s = 2, s·t = 2, t·t = 4.
        var f = Bind("""
            define frame a as basis: {x, y} Euclidean end frame
            define frame b as basis: {s, t} transform a by BCM = {{1, 1}, {0, 2}} end frame
            """).Frames["b"];
        Assert.Equal(new Rational[,] { { 2, 2 }, { 2, 4 } }, f.InnerProductMatrix.ToArray());
    }

    [Fact]
    public void Subspace_frame_takes_the_sub_block_of_the_ipm()
    {
        var f = Bind("""
            define frame c as basis: {no, e1, ni} IPM = {{0, 0, -1}, {0, 1, 0}, {-1, 0, 0}} end frame
            define frame n as basis: {ni, no} subspace of c end frame
            """).Frames["n"];
        Assert.Equal(new Rational[,] { { 0, -1 }, { -1, 0 } }, f.InnerProductMatrix.ToArray());
    }

    [Fact]
    public void Orthogonalized_frame_is_congruent_to_its_source()
    {
        var model = Bind("""
            define frame c as basis: {p, q, r} IPM = {{2, 1, 0}, {1, 2, 1}, {0, 1, 0}} end frame
            define frame o as basis: {a, b, d} orthogonalize c end frame
            """);
        var o = model.Frames["o"];
        var b = o.BasisChangeMatrix!;
        var g = model.Frames["c"].InnerProductMatrix;
        // B G Bᵀ must equal the (diagonal) IPM of the new frame.
        for (var i = 0; i < 3; i++)
        for (var j = 0; j < 3; j++)
        {
            var s = Rational.Zero;
            for (var k = 0; k < 3; k++)
            for (var l = 0; l < 3; l++)
                s += b[i, k] * g[k, l] * b[j, l];
            Assert.Equal(o.InnerProductMatrix[i, j], s);
            if (i != j) Assert.Equal(Rational.Zero, s);
        }
    }

    [Fact]
    public void Orthogonalized_degenerate_frame_keeps_its_null_direction()
    {
        // x·y = 1 and z is orthogonal to everything: x + y/2 squares to 1, the rest to −1 and 0.
        var o = Bind("""
            define frame c as basis: {x, y, z} IPM = {{0, 1, 0}, {1, 0, 0}, {0, 0, 0}} end frame
            define frame o as basis: {a, b, d} orthogonalize c end frame
            """).Frames["o"];
        Assert.Equal(new Rational[,] { { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 0 } }, o.InnerProductMatrix.ToArray());
        Assert.Equal(Rational.One, o.BasisChangeMatrix![2, 2]);
    }

    [Fact]
    public void Inverse_transform_times_transform_is_the_identity()
    {
        var model = Bind("""
            define frame a as basis: {x, y} Euclidean end frame
            define transform m : a -> a as outermorphism using {{2, 1}, {1, 1}} end transform
            define transform n : a -> a as inverse of m end transform
            define macro U as inputs: { v : a.Multivector } outputs: { w : a.Multivector } performs: w = n[m[v]]; end macro
            """);
        var m = model.Transforms["m"].VectorMatrix!;
        var n = model.Transforms["n"].VectorMatrix!;
        for (var i = 0; i < 2; i++)
        for (var j = 0; j < 2; j++)
            Assert.Equal(i == j ? Rational.One : Rational.Zero, n[i, 0] * m[0, j] + n[i, 1] * m[1, j]);
    }
}
