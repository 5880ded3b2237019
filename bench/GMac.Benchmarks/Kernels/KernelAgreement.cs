namespace GMac.Benchmarks.Kernels;

/// <summary>Checks that the three variants of a kernel compute the same outputs before any of them is timed.</summary>
public static class KernelAgreement
{
    /// <summary>Relative tolerance: the variants round differently, and some kernels divide by small numbers.</summary>
    public const double Tolerance = 1e-7;

    /// <summary>Runs every variant once and throws on the first component that differs.</summary>
    public static void Verify(IGaKernel kernel)
    {
        foreach (var v in Enum.GetValues<Variant>()) kernel.Run(v);
        for (var i = 0; i < kernel.Count; i++)
        {
            var reference = kernel.Output(Variant.Direct, i);
            foreach (var v in new[] { Variant.Generated, Variant.Hand })
            {
                var values = kernel.Output(v, i);
                if (values.Count != reference.Count)
                    throw new InvalidOperationException($"{kernel.MacroName}: {v} wrote {values.Count} components, Direct wrote {reference.Count}.");
                for (var c = 0; c < values.Count; c++)
                {
                    var a = values[c];
                    var b = reference[c];
                    var scale = Math.Max(1.0, Math.Max(Math.Abs(a), Math.Abs(b)));
                    if (!(Math.Abs(a - b) <= Tolerance * scale))
                        throw new InvalidOperationException(
                            $"{kernel.MacroName}: {v} and Direct disagree on item {i}, component {c}: {a:R} versus {b:R}.");
                }
            }
        }
    }
}
