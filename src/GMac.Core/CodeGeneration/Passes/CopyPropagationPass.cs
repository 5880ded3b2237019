namespace GMac.Core.CodeGeneration.Passes;

/// <summary>Removes temporaries that only copy a variable (or its negation) by reading the variable directly.</summary>
public sealed class CopyPropagationPass : IOptimizerPass
{
    public string Name => "copy propagation";

    public CodeBlock Run(CodeBlock block) =>
        BlockRewriting.InlineTemporaries(block, t => t.Value is VariableExpr or NegateExpr { Operand: VariableExpr });
}
