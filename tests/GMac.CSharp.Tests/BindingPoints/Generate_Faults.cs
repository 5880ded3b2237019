using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// Bad binding points: each gives a diagnostic at the right line, a non-zero exit, and leaves
/// the file byte-identical (even its other, valid regions are not rewritten).
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_Faults : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string ValidRegion = """
                #region GMac : NormalToVectors
                //GMac.Bind("u", "Vector3D", u);
                //GMac.Bind("v", "Vector3D", v);
                //GMac.Bind("w", "Vector3D", w);
                #endregion
        """;

    /// <summary>A file whose method holds a valid region (lines 7-11) and then <paramref name="tail"/> from line 12.</summary>
    private static string FileWith(string tail) => $$"""
        namespace Sample;

        public static class Faulty
        {
            public static void Run(V u, V v, V w, double a, double b)
            {
        {{ValidRegion}}
        {{tail}}
            }
        }
        """;

    private (int Exit, string Err) GenerateExpectingUntouched(string text)
    {
        var path = _temp.Write("Faulty.cs", text);
        var before = File.ReadAllBytes(path);
        var (exit, _, err) = Tool.Generate([_temp.Path]);
        Assert.Equal(before, File.ReadAllBytes(path));
        Assert.Empty(Directory.GetFiles(_temp.Path, "*.gmac-tmp"));
        return (exit, err);
    }

    [Fact]
    public void Endregion_without_region()
    {
        var (exit, err) = GenerateExpectingUntouched(FileWith("        #endregion"));
        Assert.Equal(1, exit);
        Assert.Matches(@"Faulty\.cs\(12,9\): error GMAC0401: #endregion without a matching #region", err);
    }

    [Fact]
    public void Region_without_endregion()
    {
        var (exit, err) = GenerateExpectingUntouched(FileWith("        #region GMac : NormalToVectors\n        //GMac.Bind(\"u\", \"Vector3D\", u);"));
        Assert.Equal(1, exit);
        Assert.Matches(@"Faulty\.cs\(12,9\): error GMAC0402: #region without a matching #endregion", err);
    }

    [Fact]
    public void Nested_gmac_regions()
    {
        var (exit, err) = GenerateExpectingUntouched(FileWith("""
                    #region GMac : NormalToVectors
                    //GMac.Bind("u", "Vector3D", u);
                    #region GMac : NormalToVectors
                    #endregion
                    #endregion
            """));
        Assert.Equal(1, exit);
        Assert.Matches(@"Faulty\.cs\(14,9\): error GMAC0403: region nested inside the GMac region of line 12", err);
    }

    [Fact]
    public void Unknown_macro_with_a_suggestion()
    {
        var (exit, err) = GenerateExpectingUntouched(FileWith("""
                    #region GMac : NormalToVektors
                    //GMac.Bind("u", "Vector3D", u);
                    #endregion
            """));
        Assert.Equal(1, exit);
        Assert.Matches(@"Faulty\.cs\(12,9\): error GMAC0301: unknown macro 'NormalToVektors'; did you mean 'NormalToVectors'\?", err);
    }

    [Theory]
    [InlineData("//GMac.Bind(\"u\", \"Vector3D\", u", "GMAC0404")]
    [InlineData("//GMac.Bind(\"u\")", "GMAC0404")]
    [InlineData("//GMac.Bnd(\"u\", \"Vector3D\", u);", "GMAC0404")]
    [InlineData("//GMac.Bind(u.e1, \"<a>\");", "GMAC0404")]
    [InlineData("//GMac.AssumeMin(\"a\", \"zero\");", "GMAC0404")]
    [InlineData("//GMac.Bind(\"u.e7\", \"<a>\");", "GMAC0303")]
    [InlineData("//GMac.Bind(\"q.e1\", \"<a>\");", "GMAC0302")]
    [InlineData("//GMac.Bind(\"u\", \"NoSuchBinding\", u);", "GMAC0309")]
    public void Malformed_or_wrong_bind_line(string line, string code)
    {
        var (exit, err) = GenerateExpectingUntouched(FileWith($"""
                    #region GMac : NormalToVectors
                    //GMac.Bind("v", "Vector3D", v);
                    {line}
                    //GMac.Bind("w", "Vector3D", w);
                    #endregion
            """));
        Assert.Equal(1, exit);
        Assert.Matches($@"Faulty\.cs\(14,9\): error {code}: ", err);
    }

    [Theory]
    [InlineData("//GMac.Bind(\"w.e1\", \"<a + b>\");")]
    [InlineData("//GMac.Bind(\"w.e1\", \"2\");")]
    [InlineData("//GMac.Bind(\"w.e1\", a * b);")]
    [InlineData("//GMac.Bind(\"w\", \"Vector3D\", \"Make()\");")]
    public void Output_bound_to_an_expression_that_cannot_be_assigned(string line)
    {
        var (exit, err) = GenerateExpectingUntouched(FileWith($"""
                    #region GMac : NormalToVectors
                    //GMac.Bind("u", "Vector3D", u);
                    //GMac.Bind("v", "Vector3D", v);
                    {line}
                    #endregion
            """));
        Assert.Equal(1, exit);
        Assert.Matches(@"Faulty\.cs\(15,9\): error GMAC0405: output 'w' is bound to '.+', which cannot be assigned", err);
    }

    [NotAsRootFact]
    public void Read_only_file_is_reported_and_untouched()
    {
        var path = _temp.Write("Faulty.cs", FileWith(""));
        File.SetAttributes(path, FileAttributes.ReadOnly);
        var before = File.ReadAllBytes(path);

        var (exit, _, err) = Tool.Generate([_temp.Path]);

        Assert.Equal(1, exit);
        Assert.Matches(@"Faulty\.cs\(7,9\): error GMAC0406: cannot write the generated code: the file is read-only", err);
        Assert.Equal(before, File.ReadAllBytes(path));
    }

    [Fact]
    public void Regions_inside_comments_and_strings_are_not_binding_points()
    {
        var text = FileWith("""
                    /* #region GMac : Nope
                    #endregion */
                    var s = "#region GMac : Nope";
            """).Replace(ValidRegion, "");
        var (exit, err) = GenerateExpectingUntouched(text);
        Assert.True(exit == 0, err);
    }

    [Fact]
    public void Missing_path_is_a_diagnostic()
    {
        var (exit, _, err) = Tool.Generate([Path.Combine(_temp.Path, "nope")]);
        Assert.Equal(1, exit);
        Assert.Contains("error GMAC0407: path", err);
    }
}
