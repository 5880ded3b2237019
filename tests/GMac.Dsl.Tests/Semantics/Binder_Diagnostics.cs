using GMac.Dsl.Syntax;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>One test per diagnostic kind: the offending text, the message, the position («…»).</summary>
public sealed class Binder_Diagnostics
{
    private static string Macro(string performs, string inputs = "u : e3d.Vector; v : e3d.Vector", string outputs = "w : e3d.Vector") => $$"""
        define macro M as
            inputs: { {{inputs}} }
            outputs: { {{outputs}} }
            performs:
        {{performs}}
        end macro
        """;

    [Fact]
    public void Syntax_error_names_the_unexpected_token()
    {
        var d = MarkedSource.AssertSingle("define frame e3d as basis: {e1, e2} «Euclidian» end frame", "GMAC0001");
        Assert.Contains("'Euclidian'", d.Message);
    }

    [Fact]
    public void Unknown_class_suggests_the_closest_name()
    {
        var d = MarkedSource.AssertSingle(Macro("w = u;", inputs: "u : e3d.«Vecter»"), "GMAC0101", DslSnippets.E3d);
        Assert.Equal("unknown multivector class 'e3d.Vecter'; did you mean 'e3d.Vector'?", d.Message);
    }

    [Fact]
    public void Unknown_variable_suggests_an_input()
    {
        var d = MarkedSource.AssertSingle(Macro("w = «uu» + v;"), "GMAC0101", DslSnippets.E3d);
        Assert.Equal("unknown multivector 'uu'; did you mean 'u'?", d.Message);
    }

    [Fact]
    public void Unknown_function_suggests_a_builtin()
    {
        var d = MarkedSource.AssertSingle(Macro("w = «revrse»(u);"), "GMAC0101", DslSnippets.E3d);
        Assert.Equal("unknown function or macro 'revrse'; did you mean 'reverse'?", d.Message);
    }

    [Fact]
    public void Duplicate_definition_points_at_the_first()
    {
        var d = MarkedSource.AssertSingle("""
            define frame a as basis: {x} Euclidean end frame
            define frame «a» as basis: {y} Euclidean end frame
            """, "GMAC0102");
        Assert.Equal("frame 'a' is already defined at test.gmac(1,14)", d.Message);
    }

    [Fact]
    public void Operands_from_different_frames_are_an_error()
    {
        var d = MarkedSource.AssertSingle(Macro("w = «u + x»;", inputs: "u : e3d.Vector; x : e2d.Vector"), "GMAC0110", DslSnippets.E3d);
        Assert.Equal("operands belong to different frames 'e3d' and 'e2d'", d.Message);
    }

    [Fact]
    public void Assigning_to_an_input_is_an_error()
    {
        var d = MarkedSource.AssertSingle(Macro("«u» = v;\nw = u;"), "GMAC0111", DslSnippets.E3d);
        Assert.Equal("cannot assign to input 'u'", d.Message);
    }

    [Fact]
    public void Reading_an_output_before_assignment_is_an_error()
    {
        var d = MarkedSource.AssertSingle(Macro("t = «w» + u;\nw = t;"), "GMAC0112", DslSnippets.E3d);
        Assert.Equal("output 'w' is read before it is assigned", d.Message);
    }

    [Fact]
    public void Output_of_another_frame_does_not_fit_its_class()
    {
        var d = MarkedSource.AssertSingle(Macro("«w» = x;", inputs: "x : e2d.Vector"), "GMAC0113", DslSnippets.E3d);
        Assert.Equal("value assigned to 'w' does not fit class 'e3d.Vector': the value belongs to frame 'e2d'", d.Message);
    }

    [Fact]
    public void Output_with_disjoint_grades_does_not_fit_its_class()
    {
        var d = MarkedSource.AssertSingle(Macro("«w» = u op v;"), "GMAC0113", DslSnippets.E3d);
        Assert.Equal("value assigned to 'w' does not fit class 'e3d.Vector': the value has grades {2} but the class holds grades {1}", d.Message);
    }

    [Fact]
    public void Cyclic_macro_calls_are_an_error()
    {
        var d = MarkedSource.AssertSingle("""
            define macro «A» as inputs: { u : e3d.Vector } outputs: { w : e3d.Vector } performs: w = B(u); end macro
            define macro B as inputs: { u : e3d.Vector } outputs: { w : e3d.Vector } performs: w = A(u); end macro
            """, "GMAC0114", DslSnippets.E3d);
        Assert.Equal("macro calls form a cycle: A -> B -> A", d.Message);
    }

    [Fact]
    public void Inverse_of_a_singular_transform_is_an_error()
    {
        var d = MarkedSource.AssertSingle("""
            define transform flat : e3d -> e3d as outermorphism using {{1, 0, 0}, {0, 1, 0}, {0, 0, 0}} end transform
            define transform back : e3d -> e3d as inverse of «flat» end transform
            """, "GMAC0120", DslSnippets.E3d);
        Assert.Equal("transform 'flat' is not invertible, so 'inverse of' cannot be used", d.Message);
    }

    [Fact]
    public void Matrix_of_the_wrong_size_is_an_error()
    {
        var d = MarkedSource.AssertSingle("define frame a as basis: {x, y} IPM = «{{1, 0, 0}, {0, 1, 0}}» end frame", "GMAC0121");
        Assert.Equal("matrix is 2x3 but must be 2x2", d.Message);
    }

    [Fact]
    public void Non_symmetric_ipm_is_an_error()
    {
        var d = MarkedSource.AssertSingle("define frame a as basis: {x, y} IPM = «{{1, 2}, {3, 1}}» end frame", "GMAC0122");
        Assert.Equal("inner product matrix is not symmetric: entry (1,2) differs from (2,1)", d.Message);
    }

    [Fact]
    public void Class_constant_that_is_not_an_exact_number_is_an_error()
    {
        // Generation used to read it as 0 (or throw); it is now refused where it is written.
        var d = MarkedSource.AssertSingle(
            "define multivector class e3d.Tilted as vectors; e1^e2 : «sqrt(2)» end multivector class", "GMAC0130", DslSnippets.E3d);
        Assert.Equal("invalid scalar expression: a class constant must be an exact rational constant", d.Message);
    }

    [Fact]
    public void Singular_basis_change_of_a_frame_is_an_error()
    {
        var d = MarkedSource.AssertSingle("""
            define frame a as basis: {x, y} Euclidean end frame
            define frame b as basis: {s, t} transform a by BCM = «{{1, 1}, {2, 2}}» end frame
            """, "GMAC0124");
        Assert.Equal("basis change matrix is singular", d.Message);
    }

    [Fact]
    public void Orthogonalizing_a_frame_of_another_dimension_is_an_error()
    {
        var d = MarkedSource.AssertSingle("""
            define frame a as basis: {x, y} Euclidean end frame
            define frame b as basis: {s, t, u} «orthogonalize a» end frame
            """, "GMAC0124");
        Assert.Equal("frame 'b' has 3 basis vectors but 'a' has 2", d.Message);
    }

    [Fact]
    public void Invalid_scalar_expression_text_is_an_error()
    {
        var d = MarkedSource.AssertSingle("""
            define constant e3d.K as multivector { e1 : «sin(1, 2)» } end constant
            """, "GMAC0130", DslSnippets.E3d);
        Assert.Equal("invalid scalar expression: 'sin' takes 1 argument(s), not 2", d.Message);
    }

    [Fact]
    public void Exploding_constant_power_is_refused_not_computed()
    {
        var d = MarkedSource.AssertSingle("define frame a as basis: {x} IPM = {{«((((2^64)^64)^64)^64)^64»}} end frame", "GMAC0130");
        Assert.Equal("invalid scalar expression: a matrix entry must be an exact rational constant", d.Message);
    }

    [Fact]
    public void Multivector_function_in_a_constant_scalar_is_an_error()
    {
        var d = MarkedSource.AssertSingle("define frame a as basis: {x} IPM = {{«norm(2)»}} end frame", "GMAC0130");
        Assert.Equal("invalid scalar expression: 'norm' works on multivectors and cannot appear in a constant scalar expression", d.Message);
    }

    [Fact]
    public void Temporary_used_before_its_assignment_is_an_error()
    {
        var d = MarkedSource.AssertSingle(Macro("w = «t»;\nt = u;"), "GMAC0115", DslSnippets.E3d);
        Assert.Equal("'t' is used before it is assigned", d.Message);
    }

    [Fact]
    public void Geometric_product_written_with_star_is_a_type_error()
    {
        var d = MarkedSource.AssertSingle(Macro("w = «u * v»;"), "GMAC0116", DslSnippets.E3d);
        Assert.Equal("'*' needs a scalar factor; use 'gp' for the geometric product", d.Message);
    }

    [Fact]
    public void Call_statement_missing_an_input_is_an_error()
    {
        var d = MarkedSource.AssertSingle("""
            define macro Neg as inputs: { a : e3d.Vector } outputs: { b : e3d.Vector } performs: b = -a; end macro
            define macro M as inputs: { u : e3d.Vector } outputs: { w : e3d.Vector } performs:
                «call Neg { b : w };»
            end macro
            """, "GMAC0117", DslSnippets.E3d);
        Assert.Equal("input 'a' of macro 'Neg' is not bound", d.Message);
    }

    [Fact]
    public void Signature_that_does_not_count_the_basis_is_an_error()
    {
        var d = MarkedSource.AssertSingle("define frame a as basis: {x, y} «signature (1, 0, 0)» end frame", "GMAC0124");
        Assert.Equal("signature (1, 0, 0) must count the 2 basis vectors of frame 'a'", d.Message);
    }

    [Fact]
    public void Name_of_the_wrong_kind_is_an_error()
    {
        var d = MarkedSource.AssertSingle(Macro("w = u;", inputs: "u : «e3d.vectors»"), "GMAC0103", DslSnippets.E3d);
        Assert.Equal("'e3d.vectors' is a subspace, not a multivector class", d.Message);
    }

    [Fact]
    public void Frames_defined_through_each_other_are_a_cycle()
    {
        var d = MarkedSource.AssertSingle("""
            define frame «a» as basis: {x} orthogonalize b end frame
            define frame b as basis: {y} transform a by BCM = {{2}} end frame
            """, "GMAC0123");
        Assert.Equal("frame definitions form a cycle: a -> b -> a", d.Message);
    }

    [Fact]
    public void Transforms_aliasing_each_other_are_a_cycle()
    {
        var d = MarkedSource.AssertSingle("""
            define transform «p» : e3d -> e3d as alias of q end transform
            define transform q : e3d -> e3d as alias of p end transform
            """, "GMAC0123", DslSnippets.E3d);
        Assert.Equal("transform definitions form a cycle: p -> q -> p", d.Message);
    }

    [Fact]
    public void Missing_folder_is_reported_not_thrown()
    {
        var project = DslProject.Load(Path.Combine(Path.GetTempPath(), "gmac-no-such-folder-" + Guid.NewGuid()));
        var d = Assert.Single(project.Diagnostics);
        Assert.Equal("GMAC0003", d.Code);
        Assert.True(d.IsError);
    }

    [Fact]
    public void Unused_temporary_is_a_warning()
    {
        var d = MarkedSource.AssertSingle(Macro("«t» = u op v;\nw = u;"), "GMAC0201", DslSnippets.E3d);
        Assert.Equal("temporary 't' is never used", d.Message);
        Assert.False(d.IsError);
    }

    [Fact]
    public void Unused_constant_is_a_warning()
    {
        var d = MarkedSource.AssertSingle("define constant e3d.«K» as multivector { e1 : 1 } end constant", "GMAC0201", DslSnippets.E3d);
        Assert.Equal("constant 'e3d.K' is never used", d.Message);
    }

    [Fact]
    public void Output_never_assigned_is_a_warning()
    {
        var d = MarkedSource.AssertSingle(Macro("w = u;", outputs: "w : e3d.Vector; «z» : e3d.Vector"), "GMAC0202", DslSnippets.E3d);
        Assert.Equal("output 'z' of macro 'M' is never assigned", d.Message);
        Assert.False(d.IsError);
    }

    [Theory]
    [InlineData("w = «uu» + v;", "GMAC0101")]
    [InlineData("w = «u / v»;", "GMAC0116")]
    [InlineData("call «Nope» { a : u; b : w };", "GMAC0101")]
    public void An_error_in_assigning_an_output_is_not_followed_by_never_assigned(string performs, string code)
    {
        MarkedSource.AssertSingle(Macro(performs), code, DslSnippets.E3d);
        var project = DslProject.FromSources([("test.gmac", MarkedSource.Parse(Macro(performs)).Text), ("prelude.gmac", DslSnippets.E3d)]);
        Assert.DoesNotContain(project.Diagnostics, d => d.Code == "GMAC0202");
    }

    [Theory]
    [InlineData("define frame a as basis: {x} Euclidean end frame\n«/*» the rest\ndefine frame b as basis: {y} Euclidean end frame")]
    [InlineData("define frame a as basis: {x} «/*» Euclidean end frame")]
    public void An_unclosed_block_comment_is_reported_at_its_start(string marked)
    {
        var d = MarkedSource.AssertSingle(marked, "GMAC0001");
        Assert.Equal("unterminated comment: '/*' has no closing '*/'", d.Message);
        var project = SingleFileProject.Bind(MarkedSource.Parse(marked).Text);
        Assert.Single(project.Diagnostics);
    }

    [Fact]
    public void A_long_chain_of_products_is_reported_as_deep_operator_nesting()
    {
        var factors = string.Join(" * ", Enumerable.Repeat("2", SyntaxTree.MaxOperatorChain + 2));
        var project = SingleFileProject.Bind($"define frame a as basis: {{x}} IPM = {{{{{factors}}}}} end frame");
        var d = Assert.Single(project.Diagnostics);
        Assert.Equal("GMAC0002", d.Code);
        Assert.Contains($"nests more than {SyntaxTree.MaxOperatorChain} levels deep", d.Message);
    }

    [Fact]
    public void Excessive_nesting_is_refused_before_parsing()
    {
        var text = "define frame a as basis: {x} IPM = {{" + new string('(', 300) + "1" + new string(')', 300) + "}} end frame";
        var project = SingleFileProject.Bind(text);
        var d = Assert.Single(project.Diagnostics);
        Assert.Equal("GMAC0002", d.Code);
    }

    [Fact]
    public void Many_syntax_errors_are_reported_in_one_run()
    {
        var project = SingleFileProject.Bind("""
            define frame a as basis: {x y} Euclidean end frame
            define frame b as basis: {x} Euclidian end frame
            define macro M as inputs: { } outputs: { } performs: w = ; end macro
            define frame d as basis: {x} Euclidean end frame
            """);
        var lines = project.Diagnostics.Where(d => d.Code == "GMAC0001").Select(d => d.Span.Line).Distinct().Order().ToList();
        Assert.Equal([1, 2, 3], lines);
        Assert.Contains("d", project.Model.Frames.Keys); // the intact definition is still bound
    }

    [Fact]
    public void Diagnostics_print_in_msbuild_format()
    {
        var project = SingleFileProject.Bind("define frame a as basis: {x} Euclidean end frame\ndefine frame a as basis: {x} Euclidean end frame");
        var d = Assert.Single(project.Diagnostics);
        Assert.Equal("test.gmac(2,14): error GMAC0102: frame 'a' is already defined at test.gmac(1,14)", d.ToString());
    }
}
