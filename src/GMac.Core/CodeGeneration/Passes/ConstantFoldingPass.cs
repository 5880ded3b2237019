namespace GMac.Core.CodeGeneration.Passes;

/// <summary>
/// Folds constant subexpressions (sums, products, quotients, powers and math calls of constants)
/// and propagates temporaries whose value is a constant into their uses.
/// </summary>
public sealed class ConstantFoldingPass : IOptimizerPass
{
    public string Name => "constant folding and propagation";

    public CodeBlock Run(CodeBlock block)
    {
        var folded = BlockRewriting.MapExpressions(block, e => e.Rewrite(n => n.IsLeaf ? n : ExprFactory.Normalize(n)));
        return BlockRewriting.InlineTemporaries(folded, t => t.Value is ConstantExpr);
    }
}
