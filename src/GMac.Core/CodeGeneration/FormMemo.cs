using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// What the forms of one request have built and optimized so far, so that a form that turns out to
/// be the same program as an earlier one is not built or optimized again. Building and optimizing
/// are deterministic functions of their input (scalars are hash-consed and expressions compare
/// structurally), so reusing the earlier answer gives exactly the block the work would have given.
/// </summary>
internal sealed class FormMemo
{
    private readonly List<(SymbolicProgram Program, IReadOnlyList<(string Name, Scalar Value)> Temporaries, CodeBlock Built)> _programs = [];
    private readonly List<(CodeBlock Built, CodeBlock Optimized)> _blocks = [];

    /// <summary>The block built earlier from the same program over the same temporaries, if any.</summary>
    public CodeBlock? BuiltFrom(SymbolicProgram program, IReadOnlyList<(string Name, Scalar Value)> temporaries)
    {
        foreach (var (p, t, built) in _programs)
            if (t.SequenceEqual(temporaries) && p.IsSameAs(program)) return built;
        return null;
    }

    public void Remember(SymbolicProgram program, IReadOnlyList<(string Name, Scalar Value)> temporaries, CodeBlock built) =>
        _programs.Add((program, temporaries.ToArray(), built));

    /// <summary>The reduced block (<see cref="Optimizer.Reduce"/>), from an earlier form whose built block had the same statements when there is one.</summary>
    public CodeBlock Optimized(CodeBlock built, string form)
    {
        foreach (var (b, optimized) in _blocks)
            if (b.HasSameStatements(built)) return optimized;
        var result = GenerationProfile.Time($"optimize {form}", () => Optimizer.Reduce(built));
        _blocks.Add((built, result));
        return result;
    }
}
