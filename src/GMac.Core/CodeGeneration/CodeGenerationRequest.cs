using GMac.Core.Symbolic;

namespace GMac.Core.CodeGeneration;

/// <summary>
/// Everything code generation needs for one binding point. <see cref="Evaluate"/> runs the macro
/// symbolically; given a recorder it must pass every intermediate multivector through it
/// (outside "join on" regions), and without one it yields fully expanded outputs.
/// <see cref="CodeGenerator.Generate"/> calls it up to three times, once per form it compares.
/// </summary>
public sealed record CodeGenerationRequest(
    Func<TemporaryRecorder?, SymbolicProgram> Evaluate,
    IReadOnlyDictionary<string, string> InputText,
    IReadOnlyDictionary<string, string> OutputTargets)
{
    /// <summary>Applied to every output and temporary: side relations, assumptions, the CAS.</summary>
    public Func<Scalar, Scalar>? Simplify { get; init; }

    /// <summary>
    /// The polynomial relations the inputs satisfy (the unit norm of a rotor), which <see cref="Simplify"/>
    /// may use: the accuracy probe compares the forms on inputs that satisfy them, where they agree.
    /// </summary>
    public SideRelations Relations { get; init; } = SideRelations.None;

    public JoinMode Join { get; init; } = JoinMode.Automatic;

    /// <summary>The inputs that are coordinates of points or vectors; see <see cref="CodeBlock.Points"/>.</summary>
    public IReadOnlyList<InputPoint> Points { get; init; } = [];

    /// <summary>Expressions evaluated once before the code; see <see cref="CodeBlock.EvaluatedOnce"/>.</summary>
    public IReadOnlyList<string> EvaluatedOnce { get; init; } = [];
}
