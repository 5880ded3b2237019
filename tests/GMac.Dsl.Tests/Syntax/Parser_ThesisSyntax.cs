using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Syntax;

/// <summary>The thesis spellings (§4.7-4.10) and the contract's additions parse and bind.</summary>
public sealed class Parser_ThesisSyntax
{
    private static DslProject Clean(string text)
    {
        var project = SingleFileProject.Bind(text);
        Assert.True(project.Diagnostics.Count == 0, string.Join("\n", project.Diagnostics));
        return project;
    }

    [Fact]
    public void Thesis_example_of_section_4_10_binds()
    {
        var project = Clean("""
            define frame e3d as
                basis: {e1, e2, e3}
                Euclidean
            end frame
            define constant e3d.Ii as
                multivector {e1^e2^e3 : -1}
            end constant
            define macro GetNormalToVectors as
                    inputs: {
                            u as e3d.Multivector;
                            v as e3d.Multivector
                    }
                    outputs: {
                            w as e3d.Multivector
                    }
                    performs:
                            t1 = u op v;
                            w = t1 lcp e3d.Ii;
            end macro
            """);
        var macro = project.Model.Macros["GetNormalToVectors"];
        Assert.Equal(["u", "v"], macro.Inputs.Select(i => i.Name));
        Assert.Equal(2, macro.Statements.Count);
        var op = Assert.IsType<BoundBinaryOperation>(Assert.IsType<BoundAssignment>(macro.Statements[0]).Value);
        Assert.Equal(BinaryOperator.Op, op.Operator);
    }

    [Fact]
    public void Every_frame_form_of_table_4_1_binds()
    {
        var project = Clean("""
            define frame a as basis: {x, y} Euclidean end frame
            define frame b as basis: {x} subspace of a end frame
            define frame c as basis: {p, q} IPM = {{0, -1}, {-1, 0}} end frame
            define frame d as basis: {u, v} orthogonalize c end frame
            define frame f as basis: {s, t} transform a by BCM = {{1, 1}, {0, 2}} end frame
            define frame g as basis: {e1, e2, e3, e0} signature (3, 0, 1) end frame
            """);
        var f = project.Model.Frames;
        Assert.Equal(FrameKind.Euclidean, f["a"].Kind);
        Assert.Equal(FrameKind.SubspaceOf, f["b"].Kind);
        Assert.Equal(FrameKind.InnerProductMatrix, f["c"].Kind);
        Assert.Equal(FrameKind.Orthogonalized, f["d"].Kind);
        Assert.Equal(FrameKind.TransformedByBcm, f["f"].Kind);
        Assert.Equal(FrameKind.Signature, f["g"].Kind);
    }

    [Fact]
    public void Every_transform_form_of_table_4_2_binds()
    {
        var project = Clean("""
            define frame a as basis: {x, y} Euclidean end frame
            define frame b as basis: {s, t} transform a by BCM = {{1, 1}, {0, 2}} end frame
            define transform id : a -> a as identity end transform
            define transform m : a -> a as outermorphism using {{0, -1}, {1, 0}} end transform
            define transform same : a -> a as alias of m end transform
            define transform back : a -> a as inverse of same end transform
            define transform tr : a -> a as transpose of back end transform
            define transform it : a -> a as inverse transpose of tr end transform
            define transform toA : b -> a as outermorphism using b.BCM end transform
            define subspace a.vectors as basis {x, y} end subspace
            define multivector class a.Vector as vectors end multivector class
            define macro UseAll as
                inputs: { v : a.Vector; w : b.Multivector }
                outputs: { r : a.Multivector }
                performs: r = id[v] + it[v] + toA[w] + id[m[v]];
            end macro
            """);
        Assert.Equal(7, project.Model.Transforms.Count);
        Assert.Equal(TransformKind.InverseTransposeOf, project.Model.Transforms["it"].Kind);
    }

    [Fact]
    public void Subspaces_classes_constants_and_bindings_of_4_7_bind()
    {
        var project = Clean("""
            define frame cga as basis: {no, e1, e2, ni}
                IPM = {{0, 0, 0, -1}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, 0, 0, 0}} end frame
            define subspace cga.euclidean as ga_span {e1, e2} end subspace
            define subspace cga.inf as basis {ni} end subspace
            define multivector class cga.Point as euclidean; inf; no : 1 end multivector class
            define multivector class cga.Unit as normalized; euclidean end multivector class
            define constant cga.I as multivector { no^e1^e2^ni : 1; 1 : 1/2 } end constant
            define binding P as
                use frame cga
                bind { no : 1; e1 : <x>; e2 : <y>; ni : (<x>^2 + <y>^2) / 2 }
                min { x : -1; <y> : -2.5 }
                max { x : 1 }
            end binding
            define macro M as
                inputs: { p : cga.Point; u : cga.Unit }
                outputs: { q : cga.Multivector }
                performs: q = p gp cga.I + u;
            end macro
            """);
        var point = project.Model.FindClass("cga.Point")!;
        Assert.Single(point.ConstantCoefficients);
        Assert.Equal(5, point.VariableBlades.Count); // ga_span {e1, e2} gives 1, e1, e2, e1^e2; inf adds ni
        Assert.True(project.Model.FindClass("cga.Unit")!.IsNormalized);
        Assert.Equal(-1, project.Model.ClassBindings["P"].Minimums["x"].Sign);
    }

    [Fact]
    public void All_seven_statement_kinds_and_composite_expressions_bind()
    {
        var project = Clean("""
            define frame e3d as basis: {e1, e2, e3} Euclidean end frame
            define subspace e3d.vectors as basis {e1, e2, e3} end subspace
            define subspace e3d.scalars as basis {1} end subspace
            define multivector class e3d.Vector as vectors end multivector class
            define multivector class e3d.Scalar as scalars end multivector class
            define transform id : e3d -> e3d as identity end transform
            define macro Inner as
                inputs: { a : e3d.Vector }
                outputs: { b : e3d.Vector }
                performs: b = -a;
            end macro
            define macro All as
                inputs: { u : e3d.Vector; v : e3d.Vector; t : e3d.Scalar }
                outputs: { w : e3d.Multivector; z : e3d.Vector }
                performs:
                    join on
                    m = e3d.multivector { e1 : sin(t.<1>) * u.<e1>; e2^e1 : 2; 1 : pi / 2 };
                    g = u gp v; o = u op v; s = u sp v; l = u lcp v; r = u rcp v;
                    f = u fdp v; h = u hip v; c = u cp v; k = u acp v;
                    lt = id[u];
                    un = grade_inv(m) + cliff_conj(m) + reverse(m) + scale(m, 2) + div_by_scalar(m, t.<1>)
                         + norm(u) + norm2(u) + quasi_norm(u) + quasi_norm2(u) + diff(m, t.<1>)
                         + cast_to_grades(m, 0, 2) + cast_to_grades(m, u) + cast_to_subspace(m, vectors) + cast_to_class(m, e3d.Vector)
                         + inverse(u) + dual(u) + undual(u) + grade(m, 2) + exp(o) + apply(u, v);
                    call Inner { a : u; b : z };
                    w = m + g + o + s + l + r + f + h + c + k + lt + un + Inner(v) + 2 * u / 3 - (u op v) lcp e3d.e1;
                    output { // generated comment with <w.e1^e2> and { braces } };
                    join off;
            end macro
            """);
        var kinds = project.Model.Macros["All"].Statements.Select(s => s.GetType().Name).Distinct().ToList();
        Assert.Contains(nameof(BoundJoinStatement), kinds);
        Assert.Contains(nameof(BoundCallStatement), kinds);
        Assert.Contains(nameof(BoundOutputStatement), kinds);
        Assert.Contains(nameof(BoundAssignment), kinds);
    }

    [Fact]
    public void Comments_of_both_kinds_are_ignored()
    {
        Clean("""
            // a line comment
            define frame /* inline */ e2d as basis: {e1, e2} /* multi
               line */ Euclidean end frame // trailing
            """);
    }

    [Fact]
    public void Definitions_resolve_across_files_in_any_order()
    {
        var project = DslProject.FromSources([
            ("b.gmac", "define multivector class e3d.Vector as vectors end multivector class"),
            ("a.gmac", "define subspace e3d.vectors as basis {e1, e2, e3} end subspace"),
            ("c.gmac", "define frame e3d as basis: {e1, e2, e3} Euclidean end frame"),
        ]);
        Assert.Empty(project.Diagnostics);
        Assert.NotNull(project.Model.FindClass("e3d.Vector"));
    }

    [Fact]
    public void Blade_names_in_any_order_carry_the_permutation_sign()
    {
        var project = Clean("""
            define frame e3d as basis: {e1, e2, e3} Euclidean end frame
            define constant e3d.A as multivector { e3^e2^e1 : 1; e2^e1 : 1; e3^e1 : 1; e2^e3 : 1 } end constant
            define macro M as inputs: { } outputs: { x : e3d.Multivector } performs: x = e3d.A; end macro
            """);
        var signs = project.Model.FindMember("e3d", "A") is ConstantSymbol c ? c.Coefficients.Select(k => k.Blade.Sign).ToList() : [];
        Assert.Equal([-1, -1, -1, 1], signs);
    }
}
