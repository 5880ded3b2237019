using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Vector;

namespace GMac.Benchmarks.Tests.Kernels;

/// <summary>
/// The vector forms of the kernels (generated batches in Vector256 and Vector512, and the four
/// hand-written ones) write, item by item, what the scalar generated code writes for the same item,
/// on a batch whose length is no multiple of the lanes (vector steps and scalar tail).
/// </summary>
public class VectorKernels_AgreeWithScalar
{
    public static TheoryData<string> Kernels() => new(KernelCatalog.Names);

    [Fact]
    public void Every_kernel_has_a_vector_form_and_four_have_hand_written_vector_code()
    {
        var kernels = VectorKernelCatalog.CreateAll();
        Assert.Equal(KernelCatalog.Names, kernels.Select(k => k.MacroName));
        Assert.Equal(["NormalToVectors", "SphereThroughPoints", "SquaredDistance", "RotateAboutAxisThroughPoint3D"], kernels.Where(k => k.HasHand).Select(k => k.MacroName));
    }

    [Theory]
    [MemberData(nameof(Kernels))]
    public void Every_vector_variant_agrees_item_by_item_with_the_scalar_code(string name)
    {
        var kernel = VectorKernelCatalog.CreateAll().Single(k => k.MacroName == name);
        kernel.Setup(37, seed: 11);
        VectorKernelAgreement.Verify(kernel);
        var variants = Enum.GetValues<VectorVariant>().Where(v => v != VectorVariant.Hand256 || kernel.HasHand);
        foreach (var v in variants)
        for (var i = 0; i < kernel.Count; i++)
        {
            var (vector, scalar) = (kernel.Output(v, i), kernel.Scalar.Output(Variant.Generated, i));
            Assert.Equal(scalar.Count, vector.Count);
            for (var c = 0; c < scalar.Count; c++)
                Assert.True(Math.Abs(vector[c] - scalar[c]) <= 1e-9 * Math.Max(1, Math.Abs(scalar[c])), $"{name} {v} item {i} component {c}: {vector[c]:R} vs {scalar[c]:R}");
        }
    }

    [Fact]
    public void The_check_rejects_a_vector_variant_that_computes_something_else()
    {
        var kernel = new OffByOneLane();
        kernel.Setup(9, seed: 1);
        var e = Assert.Throws<InvalidOperationException>(() => VectorKernelAgreement.Verify(kernel));
        Assert.Contains("Generated512", e.Message);
    }

    /// <summary>The cross product, with the Vector512 variant writing item 5 wrong.</summary>
    private sealed class OffByOneLane() : VectorKernel(new NormalToVectorsKernel())
    {
        protected override void Generated256(double[][] i, double[][] o) => Cross(i, o);

        protected override void Generated512(double[][] i, double[][] o)
        {
            Cross(i, o);
            o[1][5] += 1e-3;
        }

        private static void Cross(double[][] i, double[][] o)
        {
            for (var k = 0; k < i[0].Length; k++)
            {
                o[0][k] = i[1][k] * i[5][k] - i[2][k] * i[4][k];
                o[1][k] = i[2][k] * i[3][k] - i[0][k] * i[5][k];
                o[2][k] = i[0][k] * i[4][k] - i[1][k] * i[3][k];
            }
        }
    }
}
