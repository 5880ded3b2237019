using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary><c>//GMac.AssumeMin</c> / <c>AssumeMax</c> in both argument forms: accepted, verified, and checked against the bindings.</summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_Assumptions : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static string Rotation(string assumptions) => $$"""
        namespace Sample;

        public static class Rotation
        {
            public static (double, double) Rotate(double px, double py, double cr)
            {
                double qx, qy;
                #region GMac : Rotate2D
                //GMac.Bind("x.e1", px);
                //GMac.Bind("x.e2", py);
                //GMac.Bind("angle.1", cr);
                //GMac.Bind("y.e1", qx);
                //GMac.Bind("y.e2", qy);
        {{assumptions}}
                #endregion
                return (qx, qy);
            }
        }
        """;

    [Fact]
    public void Bounds_as_strings_or_literals_generate_and_verify()
    {
        var path = _temp.Write("Rotation.cs", Rotation("        //GMac.AssumeMin(\"cr\", \"0\");\n        //GMac.AssumeMax(cr, 6.2832);"));

        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        var (verified, output, verifyErr) = Tool.Verify(path);
        Assert.True(verified == 0, verifyErr + output);
        Assert.Contains("1 passed", output);
        Assert.Contains("//GMac.AssumeMax(cr, 6.2832);", File.ReadAllText(path));
    }

    [Fact]
    public void Assumption_on_an_expression_no_binding_reads_is_reported_at_its_line()
    {
        var text = Rotation("        //GMac.AssumeMin(\"angle\", \"0\");");
        var path = _temp.Write("Rotation.cs", text);

        var (exit, _, err) = Tool.Generate([path]);

        Assert.Equal(1, exit);
        Assert.Matches(@"Rotation\.cs\(14,9\): error GMAC0306: 'angle' in an assumption is not read by any binding", err);
        Assert.Equal(text, File.ReadAllText(path));
    }
}
