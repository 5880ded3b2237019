namespace GMac.CSharp.Emit;

/// <summary>Formatting choices for the C# emitters (<see cref="ICodeEmitter"/>).</summary>
public sealed record CSharpEmitOptions
{
    public string Indent { get; init; } = "";
    public string NewLine { get; init; } = "\n";

    /// <summary>
    /// The declared type of temporaries, one of <see cref="CSharpEmitter.ScalarTypes"/>. With <c>float</c>,
    /// functions are <c>MathF</c>'s and constants <c>f</c>-suffixed literals rounded once to float.
    /// </summary>
    public string ScalarType { get; init; } = "double";

    /// <summary>
    /// Writes a product added to or subtracted from a sum as one fused multiply–add
    /// (<c>Math.FusedMultiplyAdd</c>, <c>Vector256.FusedMultiplyAdd</c>, …): one rounding instead of
    /// two, so results differ from the unfused code in the last bits. Off by default.
    /// </summary>
    public bool FusedMultiplyAdd { get; init; }

    /// <summary>Adds a first comment line with the operation counts.</summary>
    public bool IncludeStatistics { get; init; }

    /// <summary>
    /// Declares each output target as a local of the scalar type where it is assigned: for outputs
    /// that no binding names, whose default names (<c>y_e1</c>) exist nowhere else.
    /// </summary>
    public bool DeclareOutputs { get; init; }

    /// <summary>
    /// Whether writing an output (by its key in <see cref="CodeBlock.OutputTargets"/>) may change what
    /// an input (by its name in <see cref="CodeBlock.InputText"/>) reads; such an output is held until
    /// no statement reads the input any more. Null: decided on the names in their texts, an approximation.
    /// </summary>
    public Func<string, string, bool>? MayOverwrite { get; init; }

    /// <summary>Names already used where the code goes; temporaries avoid them.</summary>
    public Func<string, bool> IsNameTaken { get; init; } = _ => false;
}
