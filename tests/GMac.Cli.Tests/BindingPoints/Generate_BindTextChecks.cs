using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// C# text in bind lines must be one expression (one assignable expression for an output): anything
/// else is reported at the bind line instead of being pasted into the code.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_BindTextChecks : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    /// <summary>A NormalToVectors region whose fourth line (file line 10) is <paramref name="line"/>.</summary>
    private static string FileWith(string line) => $$"""
        namespace Sample;

        public static class Checked
        {
            public static void Run(V u, V v, V w)
            {
                #region GMac : NormalToVectors
                //GMac.Bind("u", "Vector3D", u);
                //GMac.Bind("v.e1", "<v.x>");
                {{line}}
                //GMac.Bind("v.e3", "<v.z>");
                //GMac.Bind("w.e2", "<w.y>");
                //GMac.Bind("w.e3", "<w.z>");
                #endregion
            }
        }
        """;

    [Theory]
    [InlineData("//GMac.Bind(\"v.e2\", \"<v.x); System.IO.File.Delete(\\\"x\\\"); (0>\");")]
    [InlineData("//GMac.Bind(\"v.e2\", \"2 * <v.y; v.y = 0>\");")]
    [InlineData("//GMac.Bind(\"v.e2\", \"<v.y // the rest of the line>\");")]
    [InlineData("//GMac.Bind(\"w.e1\", \"<1+>\");")]
    [InlineData("//GMac.Bind(\"w.e1\", \"<w.x = 3>\");")]
    public void Text_that_is_not_one_expression_is_reported_at_its_bind_line(string line)
    {
        var path = _temp.Write("Checked.cs", FileWith(line));
        var before = File.ReadAllBytes(path);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Matches(@"Checked\.cs\(10,9\): error GMAC04\d\d: ", err);
        Assert.Equal(before, File.ReadAllBytes(path));
    }

    [Fact]
    public void Class_binding_object_must_be_one_expression()
    {
        var path = _temp.Write("Checked.cs", FileWith("//GMac.Bind(\"w\", \"Vector3D\", \"a); Evil(\");").Replace("//GMac.Bind(\"w.e2\", \"<w.y>\");", "").Replace("//GMac.Bind(\"w.e3\", \"<w.z>\");", ""));

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Matches(@"Checked\.cs\(10,9\): error GMAC04\d\d: ", err);
    }

    [Fact]
    public void Well_formed_text_still_generates()
    {
        var path = _temp.Write("Checked.cs", FileWith("//GMac.Bind(\"v.e2\", \"2 * <v.values[i + 1]> - <Math.Max(a, b)>\");"));
        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        Assert.Contains("v.values[i + 1]", File.ReadAllText(path));
    }

    [Theory]
    [InlineData("w.e1=<1+>")]
    [InlineData("u.e1=<u.x); System.IO.File.Delete(\"x\"); (0>")]
    public void Show_rejects_text_that_is_not_one_expression(string binding)
    {
        var (exit, output, err) = Tool.Run("show", "NormalToVectors", "--dsl", SharedDsl.DslDirectory,
            "--bind", binding, "--bind", "v=Vector3D:b", "--bind", "w.e2=<n.y>", "--bind", "w.e3=<n.z>");
        Assert.Equal(1, exit);
        Assert.Equal("", output);
        Assert.Contains("--bind " + binding, err);
    }

    /// <summary><c>&lt;p->x&gt;</c>: the '>' of a pointer member access does not close the template.</summary>
    [Fact]
    public void Pointer_member_access_is_an_input_as_it_is_an_output()
    {
        var path = _temp.Write("Checked.cs", FileWith("//GMac.Bind(\"v.e2\", \"<p->y>\");"));
        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        Assert.Contains("p->y", File.ReadAllText(path).Split("//GMac.Bind(\"v.e3\"")[1]);
    }
}
