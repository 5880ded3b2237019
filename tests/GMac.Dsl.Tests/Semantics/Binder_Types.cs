using GMac.Dsl.Semantics;
using GMac.Dsl.Tests.Support;

namespace GMac.Dsl.Tests.Semantics;

/// <summary>Static frames and grade sets of expressions, against the grade rules of the products.</summary>
public sealed class Binder_Types
{
    private static ExpressionType TypeOf(string expression)
    {
        var project = DslProject.FromSources([("prelude.gmac", DslSnippets.E3d), ("test.gmac", $$"""
            define macro T as
                inputs: { u : e3d.Vector; v : e3d.Vector; b : e3d.Bivector; s : e3d.Scalar }
                outputs: { x : e3d.Multivector }
                performs: x = {{expression}};
            end macro
            """)]);
        Assert.True(project.Diagnostics.All(d => !d.IsError), string.Join("\n", project.Diagnostics));
        return ((BoundAssignment)project.Model.Macros["T"].Statements.Single()).Value.Type;
    }

    private static int Grades(params int[] grades) => grades.Aggregate(0, (m, g) => m | (1 << g));

    [Theory]
    [InlineData("u gp v", new[] { 0, 2 })]
    [InlineData("u op v", new[] { 2 })]
    [InlineData("u op v op u", new[] { 3 })]
    [InlineData("u lcp b", new[] { 1 })]
    [InlineData("b lcp u", new int[0])]
    [InlineData("b rcp u", new[] { 1 })]
    [InlineData("u sp v", new[] { 0 })]
    [InlineData("b gp b", new[] { 0, 2 })]
    [InlineData("u gp b", new[] { 1, 3 })]
    [InlineData("dual(u)", new[] { 2 })]
    [InlineData("norm(b)", new[] { 0 })]
    [InlineData("exp(b)", new[] { 0, 2 })]
    [InlineData("log(exp(b))", new[] { 2 })]
    [InlineData("sqrt(exp(b))", new[] { 0, 2 })]
    [InlineData("grade(u gp b, 3)", new[] { 3 })]
    [InlineData("cast_to_grades(u gp b + s, 0, 3)", new[] { 0, 3 })]
    [InlineData("cast_to_grades(u gp b, v)", new[] { 1 })]
    [InlineData("cast_to_class(u gp b, e3d.Bivector)", new[] { 2 })]
    [InlineData("apply(u, b)", new[] { 2 })]
    [InlineData("2 * u + s", new[] { 0, 1 })]
    [InlineData("general_inverse(u)", new[] { 1 })]
    [InlineData("general_inverse(s + u)", new[] { 0, 1 })]
    [InlineData("general_inverse(s + b)", new[] { 0, 2 })]
    [InlineData("general_inverse(u + b)", new[] { 0, 1, 2, 3 })]
    public void Expression_has_the_grades_of_its_operation(string expression, int[] grades)
    {
        var type = TypeOf(expression);
        Assert.Equal("e3d", type.Frame?.Name);
        Assert.Equal(Grades(grades), type.GradeMask);
    }

    [Fact]
    public void Coefficient_access_is_a_plain_scalar()
    {
        Assert.True(TypeOf("(u op v).<e2^e1> * sin(s.<1>)").IsScalar);
    }
}
