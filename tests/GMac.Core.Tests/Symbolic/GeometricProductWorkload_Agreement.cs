using GMac.Core.Symbolic;

namespace GMac.Core.Tests.Symbolic;

public class GeometricProductWorkload_Agreement
{
    [Fact]
    public void Symbolic_5d_product_evaluates_to_the_numeric_product()
    {
        var workload = new GeometricProductWorkload(5);
        var symbolic = workload.Run();
        var random = new Random(5);
        var a = Enumerable.Range(0, 32).Select(_ => random.NextDouble() - 0.5).ToArray();
        var b = Enumerable.Range(0, 32).Select(_ => random.NextDouble() - 0.5).ToArray();
        var numeric = GeometricProductWorkload.Run(a, b);
        double Value(string name) => name[0] == 'a' ? a[int.Parse(name[1..])] : b[int.Parse(name[1..])];
        for (var k = 0; k < 32; k++)
        {
            Assert.Equal(32, symbolic[k].Terms.Count);
            Assert.Equal(numeric[k], symbolic[k].Evaluate(Value), 1e-12);
        }
    }

    [Fact]
    public void Sum_builder_gives_the_same_objects_as_operator_accumulation()
    {
        var workload = new GeometricProductWorkload(4);
        var byOperators = workload.Run();
        var byBuilder = workload.RunWithSumBuilder();
        for (var k = 0; k < byOperators.Length; k++) Assert.Same(byOperators[k], byBuilder[k]);
    }

    [Fact]
    public void Sum_builder_cancels_like_terms()
    {
        var x = Scalar.Variable("x");
        var y = Scalar.Variable("y");
        var builder = new ScalarSumBuilder();
        builder.AddProduct(x + y, x - y);
        builder.Add(y * y);
        builder.Subtract(x * x);
        Assert.Same(Scalar.Zero, builder.ToScalar());
        builder.Add(Scalar.Sin(x), 3);
        Assert.Same(Scalar.Scale(Scalar.Sin(x), 3), builder.ToScalar());
    }

    [Fact]
    public void Reordering_signs_follow_the_anticommutation_of_basis_vectors()
    {
        // e1 e2 = e12 and e2 e1 = -e12; e12 e12 = -1; e1 e12 = e2 and e12 e1 = -e2.
        Assert.Equal(1, GeometricProductWorkload.ReorderingSign(0b01, 0b10));
        Assert.Equal(-1, GeometricProductWorkload.ReorderingSign(0b10, 0b01));
        Assert.Equal(-1, GeometricProductWorkload.ReorderingSign(0b11, 0b11));
        Assert.Equal(1, GeometricProductWorkload.ReorderingSign(0b01, 0b11));
        Assert.Equal(-1, GeometricProductWorkload.ReorderingSign(0b11, 0b01));
    }
}
