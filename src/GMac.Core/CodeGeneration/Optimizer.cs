using GMac.Core.CodeGeneration.Passes;

namespace GMac.Core.CodeGeneration;

/// <summary>Runs the passes in an order where each one prepares work for the next, to a fixed point.</summary>
public sealed class Optimizer
{
    public static CodeBlock Optimize(CodeBlock block, bool reuseTemporaries = false)
    {
        var fold = new ConstantFoldingPass();
        var copy = new CopyPropagationPass();
        var strength = new StrengthReductionPass();
        var inline = new InlineSingleUsePass();
        var cse = new CommonSubexpressionPass();
        var dead = new DeadCodePass();
        var pairs = new PairExtractionPass();
        var factor = new SumFactoringPass();

        block = new TranslationInvariancePass().Run(block); // before any pass shapes sums for sharing
        block = dead.Run(copy.Run(fold.Run(block)));
        block = dead.Run(new AlgebraicValueNumberingPass().Run(block));
        block = fold.Run(strength.Run(block));
        for (var round = 0; round < 8; round++)
        {
            var before = (block.Statistics(), block.Statements.Count);
            block = inline.Run(block);
            block = copy.Run(fold.Run(block));
            block = dead.Run(cse.Run(block));
            block = dead.Run(cse.Run(pairs.Run(block)));
            block = fold.Run(factor.Run(block));
            if ((block.Statistics(), block.Statements.Count) == before) break;
        }
        block = strength.Run(block); // CSE may expose repeated denominators
        block = new SquareRootReciprocalPass().Run(new ConstantAbsorptionPass().Run(block));
        block = new ReciprocalDeferralPass().Run(block);
        block = new SineCosinePairingPass().Run(block); // last: later passes could inline the calls again
        return reuseTemporaries ? new TemporaryReusePass().Run(block) : block;
    }
}
