using GMac.Dsl.Diagnostics;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// What <see cref="SourceScanner"/> found: the files to read, the paths it could not scan
/// (errors) and the special files it left out (warnings).
/// </summary>
internal sealed record SourceScan(List<string> Files, List<Diagnostic> Problems, List<Diagnostic> Skipped);
