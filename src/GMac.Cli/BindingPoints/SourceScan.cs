namespace GMac.Cli.BindingPoints;

/// <summary>
/// What <see cref="SourceScanner"/> found: the files to read, the paths it could not scan
/// (errors) and the special files it left out (warnings: <see cref="SkippedCode"/>).
/// </summary>
internal sealed record SourceScan(List<string> Files, List<BindingDiagnostic> Problems, List<BindingDiagnostic> Skipped)
{
    public const string SkippedCode = "GMAC0411";

    /// <summary>The MSBuild form of a skipped entry, as a warning rather than an error.</summary>
    public static string AsWarning(BindingDiagnostic d) => $"{d.Path}({d.Line},{d.Column}): warning {d.Code}: {d.Message}";
}
