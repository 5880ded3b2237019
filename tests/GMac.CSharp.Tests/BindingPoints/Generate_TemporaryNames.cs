using System.Text.RegularExpressions;
using GMac.CSharp.Tests.Support;
using GMac.Core.CodeGeneration;
using GMac.CSharp.Emit;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// Names of generated temporaries: they never clash with names a binding point reads or writes, are
/// chosen per enclosing member (so many regions in one file all generate), and stay deterministic.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_TemporaryNames : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string PointType = """
        namespace Sample;

        public struct P { public double x, y, z; }
        """;

    /// <summary>A method of <c>Spheres</c> holding one SphereThroughPoints region; <paramref name="e1"/> is the C# text of p4's first coefficient.</summary>
    private static string SphereMethod(string name, string e1) => $$"""
            public static double {{name}}(P a, P b, P c, P d)
            {
                double sNo, sX, sY, sZ, sNi;
                #region GMac : SphereThroughPoints
                //GMac.Bind("p1", "ConformalPoint3D", a);
                //GMac.Bind("p2", "ConformalPoint3D", b);
                //GMac.Bind("p3", "ConformalPoint3D", c);
                //GMac.Bind("p4.e1", "{{e1}}");
                //GMac.Bind("p4.e2", "<d.y>");
                //GMac.Bind("p4.e3", "<d.z>");
                //GMac.Bind("p4.ni", "({{e1}}^2 + <d.y>^2 + <d.z>^2) / 2");
                //GMac.Bind("omega.no", "<sNo>");
                //GMac.Bind("omega.e1", "<sX>");
                //GMac.Bind("omega.e2", "<sY>");
                //GMac.Bind("omega.e3", "<sZ>");
                //GMac.Bind("omega.ni", "<sNi>");
                #endregion
                return sNo + sX + sY + sZ + sNi;
            }
        """;

    private static string SpheresFile(params string[] methods) => $$"""
        namespace Sample;

        public static partial class Spheres
        {
        {{string.Join("\n\n", methods)}}
        }
        """;

    private static List<string> DeclaredTemporaries(string text) => Regex.Matches(text, @"double (\w+) =").Select(m => m.Groups[1].Value).ToList();

    [Fact]
    public void Temporaries_avoid_a_name_read_by_a_template_even_when_it_is_declared_in_another_file()
    {
        _temp.Write("P.cs", PointType);
        _temp.Write("Fields.cs", "namespace Sample;\n\npublic static partial class Spheres { public static double tmp4 = 1.0; }\n");
        var path = _temp.Write("Spheres.cs", SpheresFile(SphereMethod("Run", "<tmp4>")));

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 0, err);
        var temporaries = DeclaredTemporaries(File.ReadAllText(path));
        Assert.NotEmpty(temporaries);
        Assert.DoesNotContain("tmp4", temporaries);
        var errors = CSharpCompile.Errors(Directory.GetFiles(_temp.Path, "*.cs"));
        Assert.True(errors.Count == 0, string.Join("\n", errors));
    }

    [Fact]
    public void Six_regions_in_six_methods_all_generate_compile_and_regenerate_identically()
    {
        _temp.Write("P.cs", PointType);
        var path = _temp.Write("Spheres.cs", SpheresFile(Enumerable.Range(1, 6).Select(i => SphereMethod($"Sphere{i}", "<d.x>")).ToArray()));

        var (exit, _, err) = Tool.Generate([path]);

        Assert.True(exit == 0, err);
        var first = File.ReadAllBytes(path);
        var errors = CSharpCompile.Errors(Directory.GetFiles(_temp.Path, "*.cs"));
        Assert.True(errors.Count == 0, string.Join("\n", errors));
        // Each method has its own scope, so each region may use the plain names.
        Assert.Equal(6, DeclaredTemporaries(File.ReadAllText(path)).Count(n => n == "tmp0"));

        File.WriteAllText(path, SpheresFile(Enumerable.Range(1, 6).Select(i => SphereMethod($"Sphere{i}", "<d.x>")).ToArray()));
        Assert.Equal(0, Tool.Generate([path]).Exit);
        Assert.Equal(first, File.ReadAllBytes(path));
        Assert.Equal(0, Tool.Generate([path]).Exit);
        Assert.Equal(first, File.ReadAllBytes(path));
    }

    [Fact]
    public void Emitter_finds_a_prefix_however_many_names_are_taken()
    {
        var context = SharedDsl.Context;
        var outcome = context.Generator.Generate("SphereThroughPoints", context.Generator.DefaultBindings("SphereThroughPoints"), 1);
        Assert.True(outcome.Succeeded);
        // Every name made of letters or underscores then a number is taken.
        var code = CSharpEmitter.Emit(outcome.Result!.Block, new CSharpEmitOptions { IsNameTaken = n => Regex.IsMatch(n, @"^[A-Za-z_]+[0-9]+$") });

        var temporaries = DeclaredTemporaries(code);
        Assert.NotEmpty(temporaries);
        Assert.All(temporaries, n => Assert.DoesNotMatch(@"^[A-Za-z_]+[0-9]+$", n));
        Assert.Equal(temporaries.Count, temporaries.Distinct().Count());
    }
}
