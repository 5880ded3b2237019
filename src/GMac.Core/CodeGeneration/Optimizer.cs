using GMac.Core.CodeGeneration.Passes;

namespace GMac.Core.CodeGeneration;

/// <summary>Runs the passes in an order where each one prepares work for the next, to a fixed point.</summary>
public sealed class Optimizer
{
    public static CodeBlock Optimize(CodeBlock block, bool reuseTemporaries = false) => Finish(Reduce(block), reuseTemporaries);

    /// <summary>
    /// The passes that can change what a block costs: what candidate forms are compared by. The
    /// generator runs them once per form and <see cref="Finish"/> once, on the form it keeps.
    /// </summary>
    public static CodeBlock Reduce(CodeBlock block)
    {
        var fold = new ConstantFoldingPass();
        var copy = new CopyPropagationPass();
        var strength = new StrengthReductionPass();
        var inline = new InlineSingleUsePass();
        var cse = new CommonSubexpressionPass();
        var dead = new DeadCodePass();
        var pairs = new PairExtractionPass();
        var factor = new SumFactoringPass();

        block = P(new TranslationInvariancePass(), block); // before any pass shapes sums for sharing
        block = P(dead, P(copy, P(fold, block)));
        block = P(dead, P(new AlgebraicValueNumberingPass(), block));
        block = P(new SharedRemainderPass(), block);
        block = P(fold, P(strength, block));
        for (var round = 0; round < 8; round++)
        {
            var before = (block.Statistics(), block.Statements.Count);
            block = P(inline, block);
            block = P(copy, P(fold, block));
            block = P(dead, P(cse, block));
            block = P(dead, P(cse, P(pairs, block)));
            block = P(fold, P(factor, block));
            if ((block.Statistics(), block.Statements.Count) == before) break;
        }
        block = P(new SumOfSquaresPass(), block);
        block = P(strength, block); // CSE may expose repeated denominators
        block = P(new SquareRootReciprocalPass(), P(new ConstantAbsorptionPass(), block));
        block = P(new ReciprocalDeferralPass(), block);
        block = P(new ArcCosinePass(), block);
        return P(new SineCosinePairingPass(), block); // last: later passes could inline the calls again
    }

    /// <summary>Passes that change no operation count and no value: signs moved into subtractions, and optionally temporaries reused.</summary>
    public static CodeBlock Finish(CodeBlock block, bool reuseTemporaries = false)
    {
        block = P(new SignPlacementPass(), block);
        return reuseTemporaries ? P(new TemporaryReusePass(), block) : block;
    }

    private static CodeBlock P(IOptimizerPass pass, CodeBlock block) => GenerationProfile.Time(pass.Name, () => pass.Run(block));
}
