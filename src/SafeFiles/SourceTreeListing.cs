namespace SafeFiles;

/// <summary>The files found under a folder, and the entries left out with the reason.</summary>
public sealed record SourceTreeListing(IReadOnlyList<string> Files, IReadOnlyList<SkippedFile> Skipped);
