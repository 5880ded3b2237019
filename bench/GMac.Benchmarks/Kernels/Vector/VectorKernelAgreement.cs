namespace GMac.Benchmarks.Kernels.Vector;

/// <summary>Checks, item by item, that every vector variant of a kernel writes what its scalar generated code writes, before any is timed.</summary>
public static class VectorKernelAgreement
{
    /// <summary>Runs every variant the kernel has (Vector512 too where it is emulated) and throws on the first component that differs.</summary>
    public static void Verify(VectorKernel kernel)
    {
        var variants = Enum.GetValues<VectorVariant>().Where(v => v != VectorVariant.Hand256 || kernel.HasHand).ToArray();
        foreach (var v in variants) kernel.Run(v);
        for (var i = 0; i < kernel.Count; i++)
        {
            var reference = kernel.Scalar.Output(Variant.Generated, i);
            foreach (var v in variants)
            {
                var values = kernel.Output(v, i);
                if (values.Count != reference.Count)
                    throw new InvalidOperationException($"{kernel.MacroName}: {v} wrote {values.Count} components, the scalar code {reference.Count}.");
                for (var c = 0; c < values.Count; c++)
                {
                    var (a, b) = (values[c], reference[c]);
                    if (!(Math.Abs(a - b) <= KernelAgreement.Tolerance * Math.Max(1.0, Math.Max(Math.Abs(a), Math.Abs(b)))))
                        throw new InvalidOperationException($"{kernel.MacroName}: {v} and the scalar generated code disagree on item {i}, component {c}: {a:R} versus {b:R}.");
                }
            }
        }
    }
}
