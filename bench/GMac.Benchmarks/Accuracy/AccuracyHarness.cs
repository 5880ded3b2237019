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
    /// The normwise relative error max |computed − exact| / max |exact| over the components: the
    /// error that matters for a vector, a rotor or a matrix, where a component near zero is not
    /// expected to be right to its own last digits.
    /// </summary>
    public static double ItemError(IReadOnlyList<double> computed, IReadOnlyList<Rational> exact)
    {
        var largest = exact.Max(e => Math.Abs(e.ToDouble()));
        var worst = 0.0;
        for (var c = 0; c < exact.Count; c++)
        {
            if (!double.IsFinite(computed[c])) return double.PositiveInfinity;
            worst = Math.Max(worst, Math.Abs((Rational.FromDouble(computed[c]) - exact[c]).ToDouble()));
        }
        return largest > 0 ? worst / largest : worst == 0 ? 0 : double.PositiveInfinity;
    }

    private static double Median(List<double> values)
    {
        var sorted = values.Order().ToArray();
        return sorted[sorted.Length / 2];
    }
}
