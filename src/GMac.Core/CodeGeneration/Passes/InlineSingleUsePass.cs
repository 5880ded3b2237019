namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Substitutes every temporary read exactly once into its reader. The tree is substituted as it
/// is, so no product is expanded and no operation is added.
/// </summary>
public sealed class InlineSingleUsePass : IOptimizerPass
{
    public string Name => "inline single-use temporaries";

    public CodeBlock Run(CodeBlock block)
    {
        var uses = BlockRewriting.UseCounts(block.Statements);
        return BlockRewriting.InlineTemporaries(block, t => uses.GetValueOrDefault(t.Target) == 1);
    }
}
