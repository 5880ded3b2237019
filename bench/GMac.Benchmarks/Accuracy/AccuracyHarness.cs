using GMac.Benchmarks.Kernels;
using GMac.Core.Numerics;
using GMac.Dsl.Generation;

namespace GMac.Benchmarks.Accuracy;

/// <summary>
/// Runs the generated and hand variants of kernels on each of their input families and compares
/// them with the exact reference (<see cref="KernelReference"/>).
/// </summary>
public sealed class AccuracyHarness(MacroCodeGenerator generator, int itemsPerFamily, int seed)
{
    /// <summary>A component smaller than this fraction of the largest one is measured against that fraction instead.</summary>
    public const double ComponentFloor = 1e-12;

    public IReadOnlyList<AccuracyRow> Measure(IGaKernel kernel)
    {
        var subject = (IAccuracySubject)kernel;
        var reference = new KernelReference(kernel, generator);
        var rows = new List<AccuracyRow>();
        foreach (var family in AccuracyFamilies.For(kernel))
        {
            var random = new Random(seed);
            subject.SetInputs(Enumerable.Range(0, itemsPerFamily).Select(_ => family.Create(random)).ToArray());
            kernel.Run(Variant.Generated);
            kernel.Run(Variant.Hand);
            var generated = new List<double>();
            var hand = new List<double>();
            for (var i = 0; i < kernel.Count; i++)
            {
                if (reference.Evaluate(i) is not { } exact) continue;
                generated.Add(ItemError(kernel.Output(Variant.Generated, i), exact));
                hand.Add(ItemError(kernel.Output(Variant.Hand, i), exact));
            }
            if (generated.Count == 0)
                throw new InvalidOperationException($"{kernel.MacroName}: the reference is undefined on every input of family '{family.Name}'");
            rows.Add(new AccuracyRow(kernel.MacroName, family, generated.Count, Median(generated), generated.Max(), Median(hand), hand.Max()));
        }
        return rows;
    }

    /// <summary>
    /// max over components of |computed − exact| / max(|exact|, <see cref="ComponentFloor"/> · largest |exact|):
    /// the relative error of every component that is not negligible next to the others.
    /// </summary>
    public static double ItemError(IReadOnlyList<double> computed, IReadOnlyList<Rational> exact)
    {
        var largest = exact.Max(e => Math.Abs(e.ToDouble()));
        var worst = 0.0;
        for (var c = 0; c < exact.Count; c++)
        {
            if (!double.IsFinite(computed[c])) return double.PositiveInfinity;
            var error = Math.Abs((Rational.FromDouble(computed[c]) - exact[c]).ToDouble());
            var scale = Math.Max(Math.Abs(exact[c].ToDouble()), ComponentFloor * largest);
            var relative = scale > 0 ? error / scale : error == 0 ? 0 : double.PositiveInfinity;
            worst = Math.Max(worst, relative);
        }
        return worst;
    }

    private static double Median(List<double> values)
    {
        var sorted = values.Order().ToArray();
        return sorted[sorted.Length / 2];
    }
}
