using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// What symbolic evaluation of a macro produces for code generation: its output coefficients and
/// verbatim text, in order, as symbolic scalars over input variables (and recorded temporaries).
/// </summary>
public sealed class SymbolicProgram
{
    public IReadOnlyList<SymbolicStatement> Statements { get; }

    public SymbolicProgram(IEnumerable<SymbolicStatement> statements) => Statements = statements.ToArray();

    /// <summary>Whether both programs have the same statements (verbatim text compared part by part).</summary>
    public bool IsSameAs(SymbolicProgram other) =>
        Statements.Count == other.Statements.Count && Statements.Zip(other.Statements).All(p => p switch
        {
            (SymbolicVerbatim a, SymbolicVerbatim b) => a.Parts.SequenceEqual(b.Parts),
            var (a, b) => a.Equals(b),
        });
}

/// <summary>One statement of a <see cref="SymbolicProgram"/>.</summary>
public abstract record SymbolicStatement;

/// <summary>An output coefficient, named as the code block's output (e.g. "w.e1").</summary>
public sealed record SymbolicOutput(string Name, Scalar Value) : SymbolicStatement;

/// <summary>Verbatim target-language text whose placeholders hold symbolic values.</summary>
public sealed record SymbolicVerbatim(IReadOnlyList<(string? Text, Scalar? Value)> Parts) : SymbolicStatement;
