using GMac.CSharp.Tests.Support;

namespace GMac.CSharp.Tests.BindingPoints;

/// <summary>
/// A batch binding point that does not read and write one item of its spans per index is an error
/// at the line that is wrong (file, line, column), and the file is left as it was.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_BatchDiagnostics : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private const string Header = """
        using System.Runtime.Intrinsics;

        public struct V3 { public double[] x, y, z; }

        public static class K
        {
            public static void Run(V3 u, V3 v, V3 w, double[] ux)
            {
                #region GMac : NormalToVectors
                //GMac.Type("Vector256<double>");

        """;

    private const string Footer = """
                #endregion
            }
        }

        """;

    [Theory]
    // Line 11 is the first line after the Type line; column 9 is where its "//" starts.
    [InlineData("//GMac.Batch(n);|//GMac.Bind(\"u\", \"Vector3D\", \"u[n]\");|//GMac.Bind(\"v\", \"Vector3D\", \"v[n]\");|//GMac.Bind(\"w\", \"Vector3D\", \"w[n]\");",
        "(11,9): error GMAC0404", "GMac.Batch takes one string")]
    [InlineData("//GMac.Batch(\"n\");|//GMac.Bind(\"u.e1\", \"<ux[n + 1]>\");|//GMac.Bind(\"u.e2\", \"<u.y[n]>\");|//GMac.Bind(\"u.e3\", \"<u.z[n]>\");|//GMac.Bind(\"v\", \"Vector3D\", \"v[n]\");|//GMac.Bind(\"w\", \"Vector3D\", \"w[n]\");",
        "(11,9): error GMAC0440", "'ux[n + 1]' uses the batch index 'n' other than")]
    [InlineData("//GMac.Batch(\"n\");|//GMac.Bind(\"u\", \"Vector3D\", \"u[n]\");|//GMac.Bind(\"v\", \"Vector3D\", \"v[n]\");|//GMac.Bind(\"w\", \"Vector3D\", \"w\");",
        "(11,9): error GMAC0440", "is written to 'w.x', the same place for every item")]
    [InlineData("//GMac.Batch(\"n\");|//GMac.Bind(\"u\", \"Vector3D\", \"u\");|//GMac.Bind(\"v\", \"Vector3D\", \"v\");|//GMac.Bind(\"w\", \"Vector3D\", \"w\");",
        "(11,9): error GMAC0440", "the same place for every item")]
    [InlineData("//GMac.Batch(\"n\");|//GMac.Bind(\"u\", \"Vector3D\", \"u[n]\");|//GMac.Bind(\"v\", \"Vector3D\", \"v[n]\");|//GMac.Batch(\"m\");|//GMac.Bind(\"w\", \"Vector3D\", \"w[n]\");",
        "(14,9): error GMAC0440", "a second GMac.Batch line")]
    [InlineData("//GMac.Batch(\"n\");|//GMac.Bind(\"u\", \"Vector3D\", \"u[n]\");|//GMac.Bind(\"v\", \"Vector3D\", \"v[n]\");",
        "(11,9): error GMAC0440", "no output of 'NormalToVectors' is bound")]
    public void A_wrong_batch_is_an_error_at_its_line_and_the_file_stays(string lines, string position, string message)
    {
        var source = Header + string.Concat(lines.Split('|').Select(l => $"        {l}\n")) + Footer;
        var path = _temp.Write("K.cs", source);
        var (exit, output, err) = Tool.Generate([_temp.Path]);
        Assert.Equal(1, exit);
        Assert.Contains($"K.cs{position}", err);
        Assert.Contains(message, err);
        Assert.Equal(source, File.ReadAllText(path));
        _ = output;
    }
}
