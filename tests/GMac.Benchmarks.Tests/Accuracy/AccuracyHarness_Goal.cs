using GMac.Benchmarks.Accuracy;
using GMac.Benchmarks.Generation;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Kernels.Values;
using GMac.Benchmarks.Tests.Support;
using GMac.Core.Numerics;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Tests.Accuracy;

public class AccuracyHarness_Goal
{
    private static readonly MacroCodeGenerator Generator = new(DslProject.Load(RepositoryPaths.Dsl));

    [Fact]
    public void Every_kernel_is_within_ten_times_the_hand_error_on_every_input_family()
    {
        var harness = new AccuracyHarness(Generator, itemsPerFamily: 16, seed: 5);
        var failures = new List<string>();
        foreach (var kernel in KernelCatalog.CreateAll())
        {
            var rows = harness.Measure(kernel);
            Assert.Contains(rows, r => r.Family.Name == "random");
            failures.AddRange(rows.Where(r => !r.Met).Select(r => $"{r.Kernel} {r.Family.Name}: generated {r.GeneratedMax:e2}, hand {r.HandMax:e2}"));
        }
        Assert.True(failures.Count == 0, string.Join("\n", failures));
    }

    [Fact]
    public void Squared_distance_of_close_points_far_out_is_exact_to_a_few_ulps_where_the_expanded_form_is_off_by_percents()
    {
        var kernel = new SquaredDistanceKernel();
        var family = AccuracyFamilies.For(kernel).Single(f => f.Name == "close-far");
        var random = new Random(3);
        ((IAccuracySubject)kernel).SetInputs(Enumerable.Range(0, 20).Select(_ => family.Create(random)).ToArray());
        kernel.Run(Variant.Generated);
        var reference = new KernelReference(kernel, Generator);
        var worstExpanded = 0.0;
        for (var i = 0; i < kernel.Count; i++)
        {
            var exact = reference.Evaluate(i)!;
            var x = (Vec3Pair)((IAccuracySubject)kernel).Input(i);
            // the expanded form the library emitted before: |a|² − 2 a·b + |b|², term by term
            var expanded = x.U.x * (x.U.x - 2 * x.V.x) + x.U.y * (x.U.y - 2 * x.V.y) + x.U.z * (x.U.z - 2 * x.V.z)
                           + x.V.x * x.V.x + x.V.y * x.V.y + x.V.z * x.V.z;
            worstExpanded = Math.Max(worstExpanded, AccuracyHarness.ItemError([expanded], exact));
            Assert.InRange(AccuracyHarness.ItemError(kernel.Output(Variant.Generated, i), exact), 0, 1e-15);
        }
        Assert.True(worstExpanded > 1e-3, $"the expanded form was accurate to {worstExpanded:e2}: the family is not ill-conditioned");
    }

    [Fact]
    public void Sphere_radius_far_out_keeps_the_hand_accuracy_that_reading_the_dual_sphere_loses()
    {
        var kernel = new SphereCentreAndRadiusThroughPointsKernel();
        var family = AccuracyFamilies.For(kernel).Single(f => f.Name == "offset");
        var random = new Random(4);
        ((IAccuracySubject)kernel).SetInputs(Enumerable.Range(0, 20).Select(_ => family.Create(random)).ToArray());
        kernel.Run(Variant.Generated);
        kernel.Run(Variant.Hand);
        var reference = new KernelReference(kernel, Generator);
        double worstGenerated = 0, worstHand = 0, worstFromDual = 0;
        for (var i = 0; i < kernel.Count; i++)
        {
            var exact = reference.Evaluate(i)!;
            worstGenerated = Math.Max(worstGenerated, AccuracyHarness.ItemError(kernel.Output(Variant.Generated, i), exact));
            worstHand = Math.Max(worstHand, AccuracyHarness.ItemError(kernel.Output(Variant.Hand, i), exact));
            // The radius read back from the dual sphere ω = α (c − ½ r² ni), α = ω_no: r² = c² − 2 ω_ni / α.
            SphereThroughPointsKernel.Generated((Vec3Quad)((IAccuracySubject)kernel).Input(i), out var omega);
            double cx = omega.E1 / omega.No, cy = omega.E2 / omega.No, cz = omega.E3 / omega.No;
            var fromDual = Math.Sqrt(cx * cx + cy * cy + cz * cz - 2 * omega.Ni / omega.No);
            worstFromDual = Math.Max(worstFromDual, AccuracyHarness.ItemError([fromDual], exact));
        }
        Assert.True(worstFromDual > 1e-9, $"the dual sphere's radius was accurate to {worstFromDual:e2}: the family is not ill-conditioned");
        Assert.True(worstGenerated <= 10 * Math.Max(worstHand, 1e-16), $"generated {worstGenerated:e2}, hand {worstHand:e2}");
        Assert.True(worstGenerated < 1e-10, $"generated {worstGenerated:e2}");
    }

    [Fact]
    public void Sphere_radius_is_generated_in_the_hand_operation_count()
    {
        var counter = new GeneratedOperationCounter(Generator);
        var kernel = new SphereCentreAndRadiusThroughPointsKernel();
        Assert.Equal(kernel.HandOperations, counter.Count(kernel));
    }

    [Fact]
    public void The_reference_writes_each_output_into_its_own_component()
    {
        var kernel = new SphereThroughPointsKernel();
        kernel.Setup(4, 11);
        kernel.Run(Variant.Hand);
        var reference = new KernelReference(kernel, Generator);
        for (var i = 0; i < kernel.Count; i++)
        {
            var exact = reference.Evaluate(i)!;
            var hand = kernel.Output(Variant.Hand, i);
            for (var c = 0; c < exact.Length; c++)
                Assert.True(Math.Abs(hand[c] - exact[c].ToDouble()) <= 1e-12 * Math.Max(1, Math.Abs(hand[c])), $"item {i}, component {c}");
        }
    }

    [Fact]
    public void Squared_distance_is_generated_in_eight_operations_like_the_hand_code()
    {
        var counter = new GeneratedOperationCounter(Generator);
        var kernel = new SquaredDistanceKernel();
        Assert.Equal(8, kernel.HandOperations.Total);
        Assert.Equal(kernel.HandOperations, counter.Count(kernel));
    }

    [Fact]
    public void The_item_error_is_normwise()
    {
        Rational[] exact = [Rational.FromDouble(1e10), Rational.One];
        Assert.Equal(0, AccuracyHarness.ItemError([1e10, 1], exact));
        // an error of 1 in the small component is 1e-10 of the output's size
        Assert.Equal(1e-10, AccuracyHarness.ItemError([1e10, 2], exact), 1e-20);
        Assert.Equal(double.PositiveInfinity, AccuracyHarness.ItemError([double.NaN, 1], exact));
    }
}
