using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// An input no line binds, or a coefficient left out of a grade whose others are bound, is an error
/// naming it, not a silent zero; a zero is written as a value. A line in a region that only looks like a //GMac. line is an error, not a comment
/// for the generated code to replace.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_UnboundInputs : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string FileWith(params string[] lines) => $$"""
        public static class Unbound
        {
            public static void Run(V u, V v, V w)
            {
                #region GMac : NormalToVectors
                {{string.Join("\n        ", lines)}}
                #endregion
            }
        }
        """;

    [Fact]
    public void An_input_bound_by_no_line_is_an_error_naming_its_coefficients()
    {
        var path = _temp.Write("Unbound.cs", FileWith("//GMac.Bind(\"u\", \"Vector3D\", u);", "//GMac.Bind(\"v.e1\", \"<v.x>\");", "//GMac.Bind(\"w\", \"Vector3D\", w);"));
        var before = File.ReadAllBytes(path);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains($"{path}(5,9): error GMAC0317: ", err);
        Assert.Contains("'v.e2', 'v.e3'", err);
        Assert.DoesNotContain("'v.e1'", err);
        Assert.Equal(before, File.ReadAllBytes(path));
    }

    [Fact]
    public void An_input_no_line_binds_is_an_error_naming_it()
    {
        var path = _temp.Write("Unbound.cs", FileWith("//GMac.Bind(\"u\", \"Vector3D\", u);", "//GMac.Bind(\"w\", \"Vector3D\", w);"));
        var before = File.ReadAllBytes(path);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains($"{path}(5,9): error GMAC0317: input 'v' of macro 'NormalToVectors' is bound by no line", err);
        Assert.Equal(before, File.ReadAllBytes(path));
    }

    /// <summary>A vector bound into a general multivector: the grades left out as a whole are zero, as the thesis binds it.</summary>
    [Fact]
    public void Grades_left_out_as_a_whole_are_zero()
    {
        var kernel = ShownKernel.Compile("GetNormalToVectors", ["u=Vector3D:a", "v.e1=<b.x>", "v.e2=<b.y>", "v.e3=<b.z>", "w=Vector3D:n"],
            "public static V[] Run(V a, V b) { V n = default; CODE return new[] { n }; }");
        double[] a = [0.3, -1.2, 0.7], b = [1.1, 0.4, -0.9];
        var n = kernel.Run(a, b)[0];
        double[] expected = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        for (var k = 0; k < 3; k++) Assert.Equal(expected[k], n[k], 12);
    }

    [Fact]
    public void A_zero_written_as_the_value_is_used()
    {
        var kernel = ShownKernel.Compile("NormalToVectors", ["u=Vector3D:a", "v.e1=<b.x>", "v.e2=<b.y>", "v.e3=0", "w=Vector3D:n"],
            "public static V[] Run(V a, V b) { V n = default; CODE return new[] { n }; }");
        double[] a = [0.3, -1.2, 0.7], b = [1.1, 0.4, -0.9];
        var n = kernel.Run(a, b)[0];
        // u × (b.x, b.y, 0)
        double[] expected = [-a[2] * b[1], a[2] * b[0], a[0] * b[1] - a[1] * b[0]];
        for (var k = 0; k < 3; k++) Assert.Equal(expected[k], n[k], 12);
    }

    [Theory]
    [InlineData("// GMac.Bind(\"v.e3\", \"<v.z>\");")]
    [InlineData("///GMac.Bind(\"v.e3\", \"<v.z>\");")]
    [InlineData("//Gmac.Bind(\"v.e3\", \"<v.z>\");")]
    [InlineData("//  gmac .Bind(\"v.e3\", \"<v.z>\");")]
    public void A_mistyped_binding_line_is_an_error(string line)
    {
        var path = _temp.Write("Unbound.cs", FileWith("//GMac.Bind(\"u\", \"Vector3D\", u);", "//GMac.Bind(\"v\", \"Vector3D\", v);", line, "//GMac.Bind(\"w\", \"Vector3D\", w);"));
        var before = File.ReadAllBytes(path);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Contains($"{path}(8,9): error GMAC0404: ", err);
        Assert.Equal(before, File.ReadAllBytes(path));
    }
}
