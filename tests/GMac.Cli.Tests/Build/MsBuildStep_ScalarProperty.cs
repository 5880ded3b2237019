namespace GMac.Cli.Tests.Build;

/// <summary>
/// The GMacScalar property of build/GMac.Build.targets on a real <c>dotnet build</c>: float code for a
/// project that asks for it (in any case: <c>Float</c>), double again when the property changes
/// (the change alone must regenerate), and a clear build error for any other value or for a
/// command line that gmac refuses.
/// </summary>
public sealed class MsBuildStep_ScalarProperty
{
    // Only the input is bound, so the generated code declares the output locals in its own scalar
    // type; the method compiles either way. The region starts empty.
    private const string Kernels = """
        namespace Sample;

        public static class Kernels
        {
            public static double Third(float ax, float ay, float az)
            {
                #region GMac : Third
                //GMac.Bind("u.e1", "<ax>");
                //GMac.Bind("u.e2", "<ay>");
                //GMac.Bind("u.e3", "<az>");
                #endregion

                return w_e1 + w_e2 + w_e3;
            }
        }

        """;

    [Fact]
    public void Gmac_scalar_float_writes_float_code_and_a_change_of_it_regenerates()
    {
        using var project = new SampleProject(Kernels, "<GMacScalar>float</GMacScalar>");
        var (exit, output) = project.Build(restore: true);
        Assert.True(exit == 0, output);
        var floatCode = File.ReadAllText(project.KernelsFile);
        Assert.Contains("float w_e1 = ", floatCode);
        Assert.Matches(@"0\.333333\d*f", floatCode); // the exact 1/3 rounded once to a float literal
        Assert.DoesNotContain("double w_", floatCode);

        SetScalar(project, "<GMacScalar>double</GMacScalar>");
        (exit, output) = project.Build();
        Assert.True(exit == 0, output);
        var doubleCode = File.ReadAllText(project.KernelsFile);
        Assert.Contains("double w_e1 = ", doubleCode);
        Assert.DoesNotMatch(@"\d+f\b", doubleCode);
    }

    [Fact]
    public void Gmac_scalar_in_capitals_writes_float_code_and_a_refused_command_line_is_explained()
    {
        using var project = new SampleProject(Kernels, "<GMacScalar>Float</GMacScalar>");
        var (exit, output) = project.Build(restore: true);
        Assert.True(exit == 0, output);
        Assert.Contains("float w_e1 = ", File.ReadAllText(project.KernelsFile));

        // An argument gmac refuses is a build error that names it, not just an exit code.
        SetScalar(project, "<GMacScalar>Float</GMacScalar><GMacGenerateArguments>--frobnicate</GMacGenerateArguments>");
        (exit, output) = project.Build();
        Assert.NotEqual(0, exit);
        Assert.Matches(@"error : gmac generate exited with code 2: [^\n]*Unrecognized option '--frobnicate'", output);
    }

    [Fact]
    public void Gmac_scalar_may_be_a_vector_type_and_the_project_builds_with_it()
    {
        const string vectorKernels = """
            using System.Runtime.Intrinsics;

            namespace Sample;

            public static class Kernels
            {
                public static Vector256<double> Third(Vector256<double> ax, Vector256<double> ay, Vector256<double> az)
                {
                    #region GMac : Third
                    //GMac.Bind("u.e1", "<ax>");
                    //GMac.Bind("u.e2", "<ay>");
                    //GMac.Bind("u.e3", "<az>");
                    #endregion

                    return w_e1 + w_e2 + w_e3;
                }
            }

            """;
        using var project = new SampleProject(vectorKernels, "<GMacScalar>vector256&lt;Double&gt;</GMacScalar>");
        var (exit, output) = project.Build(restore: true);
        Assert.True(exit == 0, output);
        var code = File.ReadAllText(project.KernelsFile);
        Assert.Contains("var w_e1 = ", code);
        Assert.Contains("Vector256.Create(0.333333", code);
    }

    [Fact]
    public void Another_gmac_scalar_is_a_build_error_naming_the_property()
    {
        using var project = new SampleProject(Kernels, "<GMacScalar>half</GMacScalar>");
        var (exit, output) = project.Build(restore: true);
        Assert.NotEqual(0, exit);
        Assert.Contains("GMacScalar is 'half'; it must be float or double", output);
        Assert.Equal(Kernels, File.ReadAllText(project.KernelsFile));
    }

    private static void SetScalar(SampleProject project, string property)
    {
        var text = File.ReadAllText(project.ProjectFile);
        var start = text.IndexOf("<GMacScalar>", StringComparison.Ordinal);
        var end = text.IndexOf("</GMacScalar>", StringComparison.Ordinal) + "</GMacScalar>".Length;
        File.WriteAllText(project.ProjectFile, text[..start] + property + text[end..]);
    }
}
