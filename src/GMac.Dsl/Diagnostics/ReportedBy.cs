namespace GMac.Dsl.Diagnostics;

/// <summary>The <c>gmac</c> commands (and the build step, which runs <c>gmac generate</c>) that can report a code.</summary>
[Flags]
public enum ReportedBy
{
    Check = 1,
    Generate = 2,
    Show = 4,
    Verify = 8,
    Build = 16,

    /// <summary><c>gmac cookbook</c>, which writes docs/cookbook.md from the library's macros and their annotations.</summary>
    Cookbook = 32,

    /// <summary>Errors in the DSL folder: every command loads it first.</summary>
    DslLoad = Check | Generate | Show | Verify | Build,

    /// <summary>Problems of one binding point's macro and bindings, wherever it is generated.</summary>
    Generation = Generate | Show | Verify | Build,

    /// <summary>Problems of the C# files read for their binding points.</summary>
    SourceFiles = Generate | Verify | Build,
}
