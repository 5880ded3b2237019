using GMac.Benchmarks.Generation;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Tests.Support;
using GMac.Dsl.Generation;
using GMac.Dsl;

namespace GMac.Benchmarks.Tests.Generation;

public class GeneratedOperationCounter_CovariantKernels
{
    /// <summary>
    /// Kernels whose outputs move with their points are generated over differences to one point
    /// for accuracy; that form must not cost more than the hand kernel, which is written the
    /// same way (½(q − p)·(q + p) for the circle, p × (q − p) for the line).
    /// </summary>
    [Theory]
    [InlineData(typeof(CircleThroughPointsKernel))]
    [InlineData(typeof(LineThroughPointsKernel))]
    public void Covariant_kernels_cost_no_more_than_the_hand_kernel(Type kernelType)
    {
        var kernel = (IGaKernel)Activator.CreateInstance(kernelType)!;
        var generated = new GeneratedOperationCounter(new MacroCodeGenerator(DslProject.Load(RepositoryPaths.Dsl))).Count(kernel);
        var hand = kernel.HandOperations;
        Assert.True(generated.Additions <= hand.Additions && generated.Multiplications <= hand.Multiplications
            && generated.Divisions <= hand.Divisions && generated.Calls <= hand.Calls, $"generated {generated}, hand {hand}");
    }
}
