using GMac.Benchmarks.Accuracy;
using GMac.Benchmarks.Kernels;
using GMac.Benchmarks.Tests.Support;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Tests.Accuracy;

public class GramSchmidtRejection_CommonPart
{
    [Fact]
    public void Generated_code_keeps_its_accuracy_on_nearly_parallel_vectors_where_the_textbook_formula_loses_digits()
    {
        var kernel = new GramSchmidtRejectionKernel();
        var family = AccuracyFamilies.For(kernel).Single(f => f.Name == "common-part");
        var random = new Random(9);
        ((IAccuracySubject)kernel).SetInputs(Enumerable.Range(0, 24).Select(_ => family.Create(random)).ToArray());
        kernel.Run(Variant.Generated);
        kernel.Run(Variant.Hand);
        var reference = new KernelReference(kernel, new MacroCodeGenerator(DslProject.Load(RepositoryPaths.Dsl)));
        double generated = 0, hand = 0;
        for (var i = 0; i < kernel.Count; i++)
        {
            var exact = reference.Evaluate(i)!;
            generated = Math.Max(generated, AccuracyHarness.ItemError(kernel.Output(Variant.Generated, i), exact));
            hand = Math.Max(hand, AccuracyHarness.ItemError(kernel.Output(Variant.Hand, i), exact));
        }
        Assert.InRange(generated, 0, 1e-15);
        Assert.True(hand > 100 * generated, $"hand {hand:e2}, generated {generated:e2}: the family is not ill-conditioned for v1 × v2");
    }
}
