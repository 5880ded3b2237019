using System.Text.RegularExpressions;
using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// Float code per binding point (<c>//GMac.Type("float");</c>) and per run (<c>--scalar float</c>):
/// what is written, that it builds with float objects, that verify checks it, and bad type names.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed partial class Generate_ScalarType : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string Dsl => SharedDsl.DslDirectory;

    /// <summary>Two binding points over float and double objects; <paramref name="floatLine"/> is the first one's type line.</summary>
    private static string Source(string floatLine, string doubleLine = "") => $$"""
        namespace Sample;

        public struct Sphere32 { public float no, e1, e2, e3, ni; }
        public struct Sphere64 { public double no, e1, e2, e3, ni; }

        public static class Spheres
        {
            public static (float, float, float, float) Centre(Sphere32 s)
            {
                #region GMac : SphereCentreAndRadius
                {{floatLine}}
                //GMac.Bind("omega", "DualSphere3D", s);
                #endregion
                return (centre_e1, centre_e2, centre_e3, radius_s);
            }

            public static (double, double, double, double) Centre(Sphere64 s)
            {
                #region GMac : SphereCentreAndRadius
                {{doubleLine}}
                //GMac.Bind("omega", "DualSphere3D", s);
                #endregion
                return (centre_e1, centre_e2, centre_e3, radius_s);
            }
        }
        """;

    private static string[] Bodies(string text) =>
        Regex.Matches(text, @"#region GMac[^\n]*\n(?<body>.*?)#endregion", RegexOptions.Singleline)
            .Select(m => string.Join("\n", m.Groups["body"].Value.Split('\n').Where(l => !l.TrimStart().StartsWith("//GMac.", StringComparison.Ordinal))))
            .ToArray();

    [Fact]
    public void A_type_line_makes_one_binding_point_float_and_verify_checks_it_as_float()
    {
        var path = _temp.Write("Spheres.cs", Source("//GMac.Type(\"float\");"));
        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        var bodies = Bodies(File.ReadAllText(path));
        Assert.Contains("float centre_e1 = ", bodies[0]);
        Assert.Contains("MathF.Sqrt(", bodies[0]);
        Assert.Contains("2.0f", bodies[0]);
        Assert.DoesNotContain("double", bodies[0]);
        Assert.Contains("double centre_e1 = ", bodies[1]);
        Assert.Contains("Math.Sqrt(", bodies[1]);
        Assert.Empty(CSharpCompile.Errors(path));

        var (verified, output, verifyErr) = Tool.Verify(path);
        Assert.True(verified == 0, verifyErr + output);
        Assert.Matches(@"ok SphereCentreAndRadius: .*\(tolerance 1e-04\)", output);
        Assert.Matches(@"ok SphereCentreAndRadius: .*\(tolerance 1e-09\)", output);
    }

    [Fact]
    public void The_scalar_option_makes_every_binding_point_without_a_type_line_float()
    {
        var path = _temp.Write("Spheres.cs", Source("", "//GMac.Type(\"double\");"));
        var cache = Path.Combine(_temp.Path, "cache");
        var (exit, _, err) = Tool.Run("generate", path, "--dsl", Dsl, "--cache", cache, "--scalar", "float");
        Assert.True(exit == 0, err);
        var bodies = Bodies(File.ReadAllText(path));
        Assert.Contains("float centre_e1 = ", bodies[0]);
        Assert.Contains("double centre_e1 = ", bodies[1]);
        Assert.Empty(CSharpCompile.Errors(path));

        // A double run sees the first region as out of date; a float run does not.
        Assert.Equal(1, Tool.Run("generate", path, "--dsl", Dsl, "--cache", cache, "--check").Exit);
        Assert.Equal(0, Tool.Run("generate", path, "--dsl", Dsl, "--cache", cache, "--check", "--scalar", "float").Exit);
        var (verified, output, verifyErr) = Tool.Run("verify", path, "--dsl", Dsl, "--cache", cache, "--scalar", "float");
        Assert.True(verified == 0, verifyErr + output);
    }

    [Fact]
    public void The_scalar_option_takes_the_type_name_in_any_case_and_names_the_types_it_refuses()
    {
        var path = _temp.Write("Spheres.cs", Source("", "//GMac.Type(\"double\");"));
        var (exit, _, err) = Tool.Run("generate", path, "--dsl", Dsl, "--cache", Path.Combine(_temp.Path, "cache"), "--scalar", "Float");
        Assert.True(exit == 0, err);
        Assert.Contains("float centre_e1 = ", Bodies(File.ReadAllText(path))[0]);

        (exit, _, err) = Tool.Run("generate", path, "--dsl", Dsl, "--scalar", "Half");
        Assert.Equal(2, exit);
        Assert.Contains("--scalar is 'Half'; it must be double or float", err);
    }

    [Theory]
    [InlineData("single", "did you mean 'float'?")]
    [InlineData("Double", "did you mean 'double'?")]
    [InlineData("decimal", "not 'decimal'")]
    [InlineData("Vector256<Double>", "did you mean 'Vector256<double>'?")]
    public void An_unknown_type_name_is_an_error_at_its_line_and_the_file_is_left_alone(string name, string message)
    {
        var text = Source($"//GMac.Type(\"{name}\");");
        var path = _temp.Write("Spheres.cs", text);
        var (exit, _, err) = Tool.Generate([path]);
        Assert.Equal(1, exit);
        Assert.Contains($"{path}(11,9): error GMAC0413: ", err);
        Assert.Contains(message, err);
        Assert.Equal(text, File.ReadAllText(path));
    }

    [Fact]
    public void A_second_type_line_is_an_error_at_that_line()
    {
        var path = _temp.Write("Spheres.cs", Source("//GMac.Type(\"float\");\n        //GMac.Type(\"float\");"));
        var (exit, _, err) = Tool.Generate([path]);
        Assert.Equal(1, exit);
        Assert.Contains($"{path}(12,9): error GMAC0413: a second GMac.Type line", err);
    }

    [Fact]
    public void A_type_that_is_not_a_string_is_an_unreadable_line()
    {
        var path = _temp.Write("Spheres.cs", Source("//GMac.Type(single);"));
        var (exit, _, err) = Tool.Generate([path]);
        Assert.Equal(1, exit);
        Assert.Contains($"{path}(11,9): error GMAC0404: GMac.Type takes one string", err);
    }

    [Fact]
    public void Show_and_generate_take_vector_types_in_any_case()
    {
        var (exit, output, err) = Tool.Run("show", "SphereCentreAndRadius", "--dsl", Dsl, "--scalar", "vector256<DOUBLE>");
        Assert.True(exit == 0, err);
        Assert.Contains("var tmpC0 = Vector256.Create(1.0);", output);
        Assert.Contains("var tmp0 = tmpC0 / omega_no;", output);
        Assert.Contains("radius_s = Vector256.Sqrt(", output);

        var path = _temp.Write("Spheres.cs", Source("", "//GMac.Type(\"Vector<float>\");"));
        (exit, _, err) = Tool.Run("generate", path, "--dsl", Dsl, "--cache", Path.Combine(_temp.Path, "cache"), "--scalar", "Vector512<Float>");
        Assert.True(exit == 0, err);
        var bodies = Bodies(File.ReadAllText(path));
        // Locals are declared with var: the broadcast constants show each region's type.
        Assert.Contains("var centre_e1 = ", bodies[0]);
        Assert.Contains("Vector512.Create(1.0f)", bodies[0]);
        Assert.Contains("var centre_e1 = ", bodies[1]);
        Assert.Contains("Vector.Create(1.0f)", bodies[1]);
        Assert.Contains("Vector.SquareRoot(", bodies[1]);
    }

    [Fact]
    public void Show_prints_float_code_and_refuses_other_scalar_types()
    {
        var (exit, output, err) = Tool.Run("show", "SphereCentreAndRadius", "--dsl", Dsl, "--scalar", "float");
        Assert.True(exit == 0, err);
        Assert.Contains("float tmp0 = 1.0f / omega_no;", output);
        Assert.Contains("radius_s = MathF.Sqrt(", output);
        Assert.Equal(2, Tool.Run("show", "SphereCentreAndRadius", "--dsl", Dsl, "--scalar", "decimal").Exit);
        Assert.Equal(2, Tool.Run("generate", ".", "--dsl", Dsl, "--scalar", "half").Exit);
    }
}
