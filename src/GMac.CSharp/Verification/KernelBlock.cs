using GMac.Core.CodeGeneration;

namespace GMac.CSharp.Verification;

/// <summary>
/// A generated block moved onto array slots (inputs <c>__in[i]</c>, outputs <c>__out[j]</c>) to be
/// compiled on its own. An output whose target is the very storage an input reads is written to
/// that input's slot, as the code in the file writes over the input; <see cref="InPlace"/> says
/// which, and the kernel copies the slot to the output afterwards.
/// </summary>
internal sealed record KernelBlock(CodeBlock Block, List<string> Inputs, List<string> Outputs)
{
    /// <summary>The hold decision the generator made on the original texts (by output key and input name).</summary>
    public Func<string, string, bool>? MayOverwrite { get; init; }

    /// <summary>Output index → the input slot it is written to.</summary>
    public IReadOnlyDictionary<int, int> InPlace { get; init; } = new Dictionary<int, int>();

    /// <summary>Whether the code is compiled with products fused into sums, as its region was generated.</summary>
    public bool FusedMultiplyAdd { get; init; }
}
