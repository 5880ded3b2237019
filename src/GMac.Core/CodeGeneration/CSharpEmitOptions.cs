namespace GMac.Core.CodeGeneration;

/// <summary>Formatting choices for <see cref="CSharpEmitter"/>.</summary>
public sealed record CSharpEmitOptions
{
    public string Indent { get; init; } = "";
    public string NewLine { get; init; } = "\n";

    /// <summary>The declared type of temporaries.</summary>
    public string ScalarType { get; init; } = "double";

    /// <summary>Adds a first comment line with the operation counts.</summary>
    public bool IncludeStatistics { get; init; }

    /// <summary>Names already used where the code goes; temporaries avoid them.</summary>
    public Func<string, bool> IsNameTaken { get; init; } = _ => false;
}
