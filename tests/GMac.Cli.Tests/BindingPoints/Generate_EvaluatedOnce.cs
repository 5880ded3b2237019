using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// A bound expression with effects (a call, an increment) runs once, as it would in hand-written
/// code, however many coefficients read it; an output target with effects is refused.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_EvaluatedOnce : IDisposable
{
    private readonly TempFolder _temp = new();

    public void Dispose() => _temp.Dispose();

    private static double[] Cross(double[] a, double[] b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

    private static readonly double[] A = [0.3, -1.2, 0.7];
    private static readonly double[] B = [1.1, 0.4, -0.9];

    [Fact]
    public void A_call_bound_as_a_whole_object_is_made_once()
    {
        var kernel = ShownKernel.Compile("NormalToVectors", ["u=Vector3D:Next()", "v=Vector3D:Next()", "w=Vector3D:n"], """
            static V[] vs = []; static int calls;
            static V Next() => vs[calls++];
            public static V[] Run(V a, V b) { vs = new[] { a, b }; calls = 0; V n = default; CODE return new[] { n, new V { x = calls } }; }
            """);
        var result = kernel.Run(A, B);
        Assert.Equal(2, result[1][0]);
        var expected = Cross(A, B);
        for (var k = 0; k < 3; k++) Assert.Equal(expected[k], result[0][k], 12);
    }

    [Fact]
    public void An_increment_in_an_object_runs_once_per_bind_line()
    {
        var kernel = ShownKernel.Compile("NormalToVectors", ["u=Vector3D:arr[i++]", "v=Vector3D:arr[i++]", "w=Vector3D:n"], """
            public static V[] Run(V a, V b) { var arr = new[] { a, b }; var i = 0; V n = default; CODE return new[] { n, new V { x = i } }; }
            """);
        var result = kernel.Run(A, B);
        Assert.Equal(2, result[1][0]);
        var expected = Cross(A, B);
        for (var k = 0; k < 3; k++) Assert.Equal(expected[k], result[0][k], 12);
    }

    [Fact]
    public void A_call_in_a_coefficient_template_is_made_once()
    {
        var kernel = ShownKernel.Compile("NormalToVectors", ["u=Vector3D:a", "v.e1=<F(b)>", "v.e2=<b.y>", "v.e3=<b.z>", "w=Vector3D:n"], """
            static int calls;
            static double F(V b) { calls++; return b.x; }
            public static V[] Run(V a, V b) { calls = 0; V n = default; CODE return new[] { n, new V { x = calls } }; }
            """);
        var result = kernel.Run(A, B);
        Assert.Equal(1, result[1][0]);
        var expected = Cross(A, B);
        for (var k = 0; k < 3; k++) Assert.Equal(expected[k], result[0][k], 12);
    }

    [Theory]
    [InlineData("//GMac.Bind(\"w\", \"Vector3D\", \"arr[i++]\");")]
    [InlineData("//GMac.Bind(\"w\", \"Vector3D\", \"Holder().v\");")]
    public void An_output_target_with_effects_is_refused_at_its_line(string line)
    {
        var path = _temp.Write("Out.cs", $$"""
            public static class Out
            {
                public static void Run(V a, V b, V[] arr, int i)
                {
                    #region GMac : NormalToVectors
                    //GMac.Bind("u", "Vector3D", a);
                    //GMac.Bind("v", "Vector3D", b);
                    {{line}}
                    #endregion
                }
            }
            """);
        var before = File.ReadAllBytes(path);
        var (exit, _, err) = Tool.Generate([path]);
        Assert.Equal(1, exit);
        Assert.Contains($"{path}(8,9): error GMAC0419: ", err);
        Assert.Equal(before, File.ReadAllBytes(path));
    }
}
