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
    public static CodeBlock Reduce(CodeBlock block) => Reduce(block, differencesEverywhere: false);

    /// <param name="differencesEverywhere">Write values that move with the points over their differences wherever that costs no more than the subtractions (see <see cref="TranslationInvariancePass"/>).</param>
    public static CodeBlock Reduce(CodeBlock block, bool differencesEverywhere)
    {
        var fold = new ConstantFoldingPass();
        var copy = new CopyPropagationPass();
        var strength = new StrengthReductionPass();
        var inline = new InlineSingleUsePass();
        var cse = new CommonSubexpressionPass();
        var dead = new DeadCodePass();
        var pairs = new PairExtractionPass();
        var factor = new SumFactoringPass();
        var known = new PassFixedPoints();
        CodeBlock Run(IOptimizerPass pass, CodeBlock input) => Once(known, pass, input);

        block = Run(new TranslationInvariancePass(differencesEverywhere), block); // before any pass shapes sums for sharing
        block = Run(dead, Run(copy, Run(fold, block)));
        block = Run(dead, Run(new AlgebraicValueNumberingPass(), block));
        block = Run(new SharedRemainderPass(), block);
        block = Run(fold, Run(strength, block));
        for (var round = 0; round < 8; round++)
        {
            var before = (block.Statistics(), block.Statements.Count);
            block = Run(inline, block);
            block = Run(copy, Run(fold, block));
            block = Run(dead, Run(cse, block));
            block = Run(dead, Run(cse, Run(pairs, block)));
            block = Run(fold, Run(factor, block));
            if ((block.Statistics(), block.Statements.Count) == before) break;
        }
        block = Run(new SumOfSquaresPass(), block);
        block = Run(strength, block); // CSE may expose repeated denominators
        block = Run(new SquareRootReciprocalPass(), Run(new ConstantAbsorptionPass(), block));
        block = Run(new ReciprocalDeferralPass(), block);
        block = Run(new ArcCosinePass(), block);
        return Run(new SineCosinePairingPass(), block); // last: later passes could inline the calls again
    }

    /// <summary>Passes that change no operation count and no value: signs moved into subtractions, divisions and calls moved first, and optionally temporaries reused.</summary>
    public static CodeBlock Finish(CodeBlock block, bool reuseTemporaries = false)
    {
        block = P(new SignPlacementPass(), block);
        block = P(new LongLatencyFirstPass(), block); // before reuse, which depends on the order
        return reuseTemporaries ? P(new TemporaryReusePass(), block) : block;
    }

    private static CodeBlock P(IOptimizerPass pass, CodeBlock block) => GenerationProfile.Time(pass.Name, () => pass.Run(block));

    /// <summary>Runs the pass unless it is known to leave the block as it is; its result is one of its fixed points.</summary>
    private static CodeBlock Once(PassFixedPoints known, IOptimizerPass pass, CodeBlock block)
    {
        if (known.Contains(pass, block)) return block;
        var result = P(pass, block);
        PassObserver?.Invoke(pass, result);
        known.Add(pass, result);
        return result;
    }

    /// <summary>Sees every pass run of <see cref="Reduce"/> on this thread with its result: how tests check that skipping fixed points is exact.</summary>
    [ThreadStatic]
    internal static Action<IOptimizerPass, CodeBlock>? PassObserver;
}
