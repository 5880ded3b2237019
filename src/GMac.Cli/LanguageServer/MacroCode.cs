using GMac.Core.CodeGeneration;

namespace GMac.Cli.LanguageServer;

/// <summary>A macro's generated code and its counts, or why there is none.</summary>
internal sealed record MacroCode(CodeStatistics? Statistics, string? Code, string? Problem);
