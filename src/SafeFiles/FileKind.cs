namespace SafeFiles;

/// <summary>What a path names, after following symbolic links.</summary>
public enum FileKind
{
    /// <summary>The operating system could not say (missing path, dangling link, or a platform without the query).</summary>
    Unknown,
    Regular,
    Directory,

    /// <summary>A FIFO, socket or device: reading one may block forever or never end.</summary>
    Special,
}
