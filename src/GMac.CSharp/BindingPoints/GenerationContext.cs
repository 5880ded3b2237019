using GMac.Core.Symbolic;
using GMac.Dsl;
using GMac.Dsl.Generation;

namespace GMac.CSharp.BindingPoints;

/// <summary>
/// A loaded GMacDSL project with its code generator and the on-disk simplification cache, shared
/// by every binding point of one run.
/// </summary>
internal sealed class GenerationContext
{
    public const string DefaultCacheFolder = ".gmac-cache";

    public GenerationContext(DslProject project, string? cacheDirectory)
    {
        Project = project;
        CacheDirectory = cacheDirectory;
        // Answers are only valid for the simplifier that gave them, so each build of GMac.Core
        // gets its own sub-folder (a changed rule set must not be served stale results).
        Cache = new SimplificationCache(cacheDirectory is null ? null : Path.Combine(cacheDirectory, $"core-{ToolVersion[..12]}"));
        Cas = new CachingCasAdapter(new RuleBasedCas(), Cache);
        Generator = new MacroCodeGenerator(project, Cas);
    }

    public DslProject Project { get; }

    /// <summary>The scalar type of binding points without a <c>//GMac.Type</c> line (<c>--scalar</c>).</summary>
    public string DefaultScalarType { get; set; } = "double";

    /// <summary>Whether binding points without a <c>//GMac.Fma</c> line fuse products into sums (<c>--fma</c>).</summary>
    public bool DefaultFusedMultiplyAdd { get; set; }

    /// <summary>The caching simplifier behind the generator (its hits include answers found by identity).</summary>
    public CachingCasAdapter Cas { get; }

    /// <summary>Where caches persist between runs; null keeps them in memory.</summary>
    public string? CacheDirectory { get; }
    public SimplificationCache Cache { get; }
    public MacroCodeGenerator Generator { get; }

    /// <summary>Identifies the generator's code (deterministic builds: it changes only when the code does).</summary>
    public static string ToolVersion { get; } = string.Concat(
        new[] { typeof(RuleBasedCas), typeof(DslProject), typeof(GenerationContext) }.Select(t => t.Assembly.ManifestModule.ModuleVersionId.ToString("N")));

    /// <summary>The cache folder used when none is given: <c>.gmac-cache/</c> inside the DSL folder (gitignored).</summary>
    public static string DefaultCacheDirectory(string dslDirectory) => Path.Combine(Path.GetFullPath(dslDirectory), DefaultCacheFolder);
}
