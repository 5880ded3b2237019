using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// Vector regions in files that do not import System.Runtime.Intrinsics (or System.Numerics): the
/// generated code names the vector types in full, so the file compiles as it is; files that import
/// the namespace keep the short names.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_VectorNamesWithoutUsing : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string Source(string usings, string type, string e = "double") => usings + $$"""

        namespace Plain;

        public static class Kernels
        {
            public static void Rotate({{e}}[] rs, {{e}}[] rxy, {{e}}[] ryz, {{e}}[] rzx, {{e}}[] px, {{e}}[] py, {{e}}[] pz, {{e}}[] qx, {{e}}[] qy, {{e}}[] qz)
            {
                #region GMac : ApplyUnitRotor3D
                //GMac.Type("{{type}}");
                //GMac.Batch("i");
                //GMac.Bind("r.1", "<rs[i]>");
                //GMac.Bind("r.e1^e2", "<rxy[i]>");
                //GMac.Bind("r.e2^e3", "<ryz[i]>");
                //GMac.Bind("r.e3^e1", "<rzx[i]>");
                //GMac.Bind("x.e1", "<px[i]>");
                //GMac.Bind("x.e2", "<py[i]>");
                //GMac.Bind("x.e3", "<pz[i]>");
                //GMac.Bind("y.e1", "<qx[i]>");
                //GMac.Bind("y.e2", "<qy[i]>");
                //GMac.Bind("y.e3", "<qz[i]>");
                #endregion
            }
        }
        """;

    private string Generate(string usings, string type)
    {
        var path = _temp.Write("Plain/Kernels.cs", Source(usings, type, type.Contains("float", StringComparison.Ordinal) ? "float" : "double"));
        var (exit, output, err) = Tool.Generate([_temp.Path]);
        Assert.True(exit == 0, err + output);
        return path;
    }

    [Theory]
    [InlineData("Vector256<double>", "global::System.Runtime.Intrinsics.Vector256")]
    [InlineData("Vector128<float>", "global::System.Runtime.Intrinsics.Vector128")]
    [InlineData("Vector<double>", "global::System.Numerics.Vector")]
    public void Without_the_using_the_vector_names_are_qualified_and_the_file_compiles(string type, string qualified)
    {
        var path = Generate("", type);
        var text = File.ReadAllText(path);
        Assert.Contains(qualified + "<", text);
        Assert.True(CSharpCompile.Errors(path).Count == 0, string.Join("\n", CSharpCompile.Errors(path)) + "\n" + text);
        var family = type[..type.IndexOf('<')];
        // Every use of the family inside the region is qualified; none is left bare.
        var code = string.Join("\n", text.Replace(qualified, "", StringComparison.Ordinal).Split('\n').Where(l => !l.TrimStart().StartsWith("//", StringComparison.Ordinal)));
        Assert.DoesNotMatch($@"(?<![.\w]){family}[<.]", code);
    }

    [Fact]
    public void With_the_using_the_short_names_stay()
    {
        var path = Generate("using System.Runtime.Intrinsics;\n", "Vector256<double>");
        var text = File.ReadAllText(path);
        Assert.Contains("Vector256<double>", text);
        Assert.DoesNotContain("global::System.Runtime.Intrinsics", text);
        Assert.Empty(CSharpCompile.Errors(path));
    }

    [Fact]
    public void Qualified_regions_are_current_for_generate_check_and_pass_verify()
    {
        Generate("", "Vector256<double>");
        var (exit, output, err) = Tool.Generate([_temp.Path], check: true);
        Assert.True(exit == 0, err + output);
        (exit, output, err) = Tool.Verify(_temp.Path);
        Assert.True(exit == 0, err + output);
    }
}
