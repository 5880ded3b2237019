using System.Text.RegularExpressions;
using GMac.CSharp.BindingPoints;
using GMac.CSharp.Tests.Support;
using GMac.CSharp.Verification;

namespace GMac.Cli.Tests.Verification;

/// <summary>
/// <c>gmac verify</c> compiles each region inside its own file and project: code that would not
/// build there fails verification, at its position, even when its numbers are right.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Verify_InProjectContext : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string Project = """
        <Project Sdk="Microsoft.NET.Sdk">
          <PropertyGroup>
            <TargetFramework>net10.0</TargetFramework>
            <ImplicitUsings>enable</ImplicitUsings>
          </PropertyGroup>
        </Project>
        """;

    private const string Types = """
        namespace Sample;

        public sealed class V
        {
            public double x { get; set; }
            public double y { get; set; }
            public double z { get; set; }
            public double Length { get; }
        }
        """;

    /// <summary>A NormalToVectors region (lines 7-13) whose last output is bound to <paramref name="e3"/>.</summary>
    private static string Normals(string e3) => $$"""
        namespace Sample;

        public static class Normals
        {
            public static void Run(V u, V v, V w)
            {
                #region GMac : NormalToVectors
                //GMac.Bind("u", "Vector3D", u);
                //GMac.Bind("v", "Vector3D", v);
                //GMac.Bind("w.e1", "<w.x>");
                //GMac.Bind("w.e2", "<w.y>");
                //GMac.Bind("w.e3", "{{e3}}");
                #endregion
            }
        }
        """;

    private string WriteProject(string e3)
    {
        _temp.Write("Sample/Sample.csproj", Project);
        _temp.Write("Sample/Types/V.cs", Types);
        return _temp.Write("Sample/Normals.cs", Normals(e3));
    }

    [Fact]
    public void Good_region_passes()
    {
        WriteProject("<w.z>");
        var (exit, output, err) = Tool.Verify(_temp.Path);
        Assert.True(exit == 0, err + output);
        Assert.Contains("gmac verify: 1 region(s), 1 passed, 0 problem(s)", output);
    }

    [Fact]
    public void Output_bound_to_a_get_only_property_fails_at_the_assignment()
    {
        WriteProject("<w.Length>");
        var (exit, output, err) = Tool.Verify(_temp.Path);
        Assert.Equal(1, exit);
        Assert.Matches(@"Normals\.cs\(1[3-5],\d+\): error GMAC0422: .*CS0200", err);
        Assert.Contains("0 passed", output);
    }

    [Fact]
    public void Region_body_that_does_not_compile_in_its_method_fails()
    {
        var path = WriteProject("<w.z>");
        var context = SharedDsl.Context;
        var generation = SourceGeneration.GenerateFile(path, context, stats: false, new StringWriter())!;
        Assert.True(generation.Succeeded);
        // A body whose temporary reads itself, as a clashing name would make it.
        var region = generation.Regions[0];
        var clashing = generation with { Regions = [region with { Code = "        double u = u * 2.0;\n" + region.Code }] };

        var failures = ProjectContextCompiler.Check([clashing]);

        var error = Assert.Single(failures).Diagnostic;
        Assert.Equal("GMAC0422", error.Code);
        Assert.Equal(13, error.Span.Line);
        Assert.InRange(error.Span.Column, 9, 30);
        Assert.Contains("NormalToVectors", error.Message);
    }

    [Fact]
    public void Without_a_project_the_files_of_the_same_folder_are_the_context()
    {
        _temp.Write("Types.cs", Types + "\npublic static class Store { public static double Last; }\n");
        _temp.Write("Normals.cs", Normals("<Store.Last>"));
        var (exit, output, err) = Tool.Verify(_temp.Path);
        Assert.True(exit == 0, err + output);
        Assert.Contains("1 passed", output);
    }

    [Fact]
    public void Path_without_binding_points_is_reported()
    {
        _temp.Write("Types.cs", Types);
        var (exit, output, err) = Tool.Verify(_temp.Path);
        Assert.Equal(1, exit);
        Assert.Matches(new Regex("no binding points", RegexOptions.IgnoreCase), err + output);
    }
}
