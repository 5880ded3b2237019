namespace GMac.CSharp.Docs;

/// <summary>A section of the cookbook: the macros of one library file (or moved to it by a <c>cookbook group:</c> line).</summary>
internal sealed record CookbookGroup(int Order, string Title, string Intro, string File, IReadOnlyList<CookbookEntry> Entries);
