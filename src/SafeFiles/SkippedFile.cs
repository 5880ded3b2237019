namespace SafeFiles;

/// <summary>
/// An entry a folder walk left out, and why: a special file (a warning: it holds no source) or a
/// folder that could not be listed (an error: its files are missing).
/// </summary>
public sealed record SkippedFile(string Path, string Reason, bool IsError);
