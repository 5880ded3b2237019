namespace GMac.Cli.BindingPoints;

/// <summary>A problem with a binding point or its file, printed in the MSBuild format.</summary>
internal sealed record BindingDiagnostic(string Path, int Line, int Column, string Code, string Message)
{
    public override string ToString() => $"{Path}({Line},{Column}): error {Code}: {Message}";
}
