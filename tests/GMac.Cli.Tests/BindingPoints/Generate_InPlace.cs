using GMac.CSharp.Tests.Support;

namespace GMac.Cli.Tests.BindingPoints;

/// <summary>
/// An output bound to the very variable an input reads (<c>a = a × b</c>) must give what the same
/// binding point gives with separate variables: the generated code may not overwrite an input
/// that later statements still read.
/// </summary>
[Collection(SharedDslCollection.Name)]
public sealed class Generate_InPlace
{
    [Fact]
    public void Cross_product_into_its_own_first_operand()
    {
        var kernel = ShownKernel.Compile("NormalToVectors", ["u=Vector3D:a", "v=Vector3D:b", "w=Vector3D:a"], "public static V[] Run(V a, V b) { CODE return new[] { a }; }");
        var random = new Random(7);
        for (var i = 0; i < 20; i++)
        {
            var (a, b) = (Coordinates(random), Coordinates(random));
            var w = kernel.Run(a, b)[0];
            // w = u × v, written over u's own components
            double[] cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
            for (var k = 0; k < 3; k++) Assert.Equal(cross[k], w[k], 12);
        }
    }

    [Fact]
    public void Gram_schmidt_by_rejection_into_its_own_inputs()
    {
        var inPlace = ShownKernel.Compile("GramSchmidtRejection", ["v1=Vector3D:a", "v2=Vector3D:b", "v3=Vector3D:c", "w1=Vector3D:a", "w2=Vector3D:b", "w3=Vector3D:c"],
            "public static V[] Run(V a, V b, V c) { CODE return new[] { a, b, c }; }");
        var apart = ShownKernel.Compile("GramSchmidtRejection", ["v1=Vector3D:a", "v2=Vector3D:b", "v3=Vector3D:c", "w1=Vector3D:r", "w2=Vector3D:s", "w3=Vector3D:t"],
            "public static V[] Run(V a, V b, V c) { V r = default, s = default, t = default; CODE return new[] { r, s, t }; }");
        var random = new Random(8);
        for (var i = 0; i < 20; i++)
        {
            double[][] v = [Coordinates(random), Coordinates(random), Coordinates(random)];
            Assert.Equal(apart.Run(v).SelectMany(x => x), inPlace.Run(v).SelectMany(x => x));
        }
    }

    /// <summary>u × v written over u, with u and w spelt differently but naming the same storage.</summary>
    [Theory]
    [InlineData("u=Vector3D:ψ", "w=Vector3D:ψ", "public static V[] Run(V ψ, V b) { CODE return new[] { ψ }; }")]
    [InlineData("u=Vector3D:p", "w=Vector3D:this.p", "public sealed class H { public V p; public void Go(V b) { CODE } } public static V[] Run(V a, V b) { var h = new H { p = a }; h.Go(b); return new[] { h.p }; }")]
    [InlineData("u=Vector3D:@a", "w=Vector3D:(a)", "public static V[] Run(V a, V b) { CODE return new[] { a }; }")]
    [InlineData("u=Vector3D:arr[i]", "w=Vector3D:arr[j]", "public static V[] Run(V a, V b) { var arr = new[] { a }; int i = 0, j = 0; CODE return new[] { arr[0] }; }")]
    public void Cross_product_into_its_own_operand_spelt_another_way(string u, string w, string method)
    {
        var kernel = ShownKernel.Compile("NormalToVectors", [u, "v=Vector3D:b", w], method);
        var random = new Random(9);
        for (var i = 0; i < 5; i++)
        {
            var (a, b) = (Coordinates(random), Coordinates(random));
            var result = kernel.Run(a, b)[0];
            double[] cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
            for (var k = 0; k < 3; k++) Assert.Equal(cross[k], result[k], 12);
        }
    }

    /// <summary>Two ref parameters may be one variable: the generated file, called with the same variable twice, still computes u × v.</summary>
    [Fact]
    public void Ref_parameters_that_are_one_variable()
    {
        using var temp = new TempFolder();
        var path = temp.Write("Refs.cs", """
            public struct V { public double x, y, z; }
            public static class Kernel
            {
                public static void Go(ref V a, V b, ref V n)
                {
                    #region GMac : NormalToVectors
                    //GMac.Bind("u", "Vector3D", a);
                    //GMac.Bind("v", "Vector3D", b);
                    //GMac.Bind("w", "Vector3D", n);
                    #endregion
                }

                public static V[] Run(V a, V b) { Go(ref a, b, ref a); return new[] { a }; }
            }
            """);
        var (exit, _, err) = Tool.Generate([path]);
        Assert.True(exit == 0, err);
        var kernel = ShownKernel.Load(File.ReadAllText(path));
        double[] a = [0.3, -1.2, 0.7], b = [1.1, 0.4, -0.9];
        var result = kernel.Run(a, b)[0];
        double[] cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        for (var k = 0; k < 3; k++) Assert.Equal(cross[k], result[k], 12);
    }

    private static double[] Coordinates(Random random) => [random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1];
}
