using GMac.Benchmarks.Kernels;

namespace GMac.Benchmarks.Tests.Kernels;

public class KernelAgreement_AllVariants
{
    public static TheoryData<string> Kernels() => new(KernelCatalog.Names);

    [Fact]
    public void The_catalog_holds_the_thirteen_kernels_of_the_suite_first_then_the_added_ones()
    {
        Assert.Equal(
            ["HiddenSurface", "VortexS", "Circ3", "GramSchmidtContraction", "GramSchmidtRejection", "RotorToMatrix", "JuliaStep3",
             "JuliaStep5", "RotorInterpolate", "SkewLinesClosestPoints", "NormalToVectors", "SphereThroughPoints", "ApplyTwistToPoint3D"],
            KernelCatalog.Names.Take(13));
        Assert.Contains("SquaredDistance", KernelCatalog.Names);
        Assert.Contains("RotateAboutAxisThroughPoint3D", KernelCatalog.Names);
        Assert.Equal(KernelCatalog.Names.Count, KernelCatalog.Names.Distinct().Count());
    }

    [Theory]
    [MemberData(nameof(Kernels))]
    public void Generated_direct_and_hand_variants_agree_on_a_batch(string name)
    {
        var kernel = KernelCatalog.Create(name);
        kernel.Setup(64, seed: 7);
        KernelAgreement.Verify(kernel);
        Assert.All(Enum.GetValues<Variant>(), v => Assert.All(kernel.Output(v, 0), c => Assert.True(double.IsFinite(c))));
    }

    [Fact]
    public void The_check_rejects_a_variant_that_computes_something_else()
    {
        var kernel = new SkewedKernel();
        kernel.Setup(8, seed: 1);
        var e = Assert.Throws<InvalidOperationException>(() => KernelAgreement.Verify(kernel));
        Assert.Contains("Hand", e.Message);
    }

    [Fact]
    public void Unknown_kernel_names_are_reported_with_the_known_ones()
    {
        var e = Assert.Throws<ArgumentException>(() => KernelCatalog.Create("NoSuchMacro"));
        Assert.Contains("HiddenSurface", e.Message);
    }

    /// <summary>A kernel whose hand variant is off by a relative 1e-6, above the tolerance.</summary>
    private sealed class SkewedKernel : GaKernel<double, double>
    {
        public override string MacroName => "Skewed";
        public override string Source => "test";
        public override OperationCount HandOperations => new(0, 1, 0, 0);
        protected override double CreateInput(Random random) => random.NextDouble() + 1;
        protected override double[] Components(double value) => [value];
        protected override void RunGenerated(double[] inputs, double[] outputs) => inputs.CopyTo(outputs, 0);
        protected override void RunDirect(double[] inputs, double[] outputs) => inputs.CopyTo(outputs, 0);

        protected override void RunHand(double[] inputs, double[] outputs)
        {
            for (var i = 0; i < inputs.Length; i++) outputs[i] = inputs[i] * (1 + 1e-6);
        }
    }
}
