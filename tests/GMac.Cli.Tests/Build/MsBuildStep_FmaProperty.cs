namespace GMac.Cli.Tests.Build;

/// <summary>
/// The GMacFma property of build/GMac.Build.targets on a real <c>dotnet build</c>: <c>true</c> writes
/// fused multiply–adds into binding points (as <c>--fma</c>), and a value other than true or false
/// is a build error naming the property.
/// </summary>
public sealed class MsBuildStep_FmaProperty
{
    private const string Kernels = """
        using System;

        namespace Sample;

        public static class Kernels
        {
            public static double Cross(double ax, double ay, double az, double bx, double by, double bz)
            {
                #region GMac : Cross
                //GMac.Bind("u.e1", "<ax>");
                //GMac.Bind("u.e2", "<ay>");
                //GMac.Bind("u.e3", "<az>");
                //GMac.Bind("v.e1", "<bx>");
                //GMac.Bind("v.e2", "<by>");
                //GMac.Bind("v.e3", "<bz>");
                #endregion

                return w_e1 + w_e2 + w_e3;
            }
        }

        """;

    private const string Cross = """
        define macro Cross as
            inputs: { u : e3d.Vector; v : e3d.Vector }
            outputs: { w : e3d.Vector }
            performs:
                w = u + (u lcp v) * v;
        end macro
        """;

    [Fact]
    public void Gmac_fma_true_writes_fused_multiply_adds_and_the_project_builds()
    {
        using var project = new SampleProject(Kernels, "<GMacFma>True</GMacFma>");
        project.Write(Path.Combine("dsl", "cross.gmac"), Cross);
        var (exit, output) = project.Build(restore: true);
        Assert.True(exit == 0, output);
        Assert.Contains("Math.FusedMultiplyAdd(", File.ReadAllText(project.KernelsFile));
    }

    [Fact]
    public void Another_gmac_fma_is_a_build_error_naming_the_property()
    {
        using var project = new SampleProject(Kernels, "<GMacFma>maybe</GMacFma>");
        project.Write(Path.Combine("dsl", "cross.gmac"), Cross);
        var (exit, output) = project.Build(restore: true);
        Assert.NotEqual(0, exit);
        Assert.Contains("GMacFma is 'maybe'; it must be true or false", output);
        Assert.Equal(Kernels, File.ReadAllText(project.KernelsFile));
    }
}
