namespace RayTracer.Geometry.Meshes;

/// <summary>
/// A mesh file is malformed or truncated. Carries the file name and the line (and column, where known)
/// or byte offset of the problem.
/// </summary>
public sealed class MeshFormatException : Exception
{
    public MeshFormatException(string fileName, string problem, int? line = null, long? byteOffset = null, int? column = null)
        : base(Format(fileName, problem, line, byteOffset, column))
    {
        FileName = fileName;
        Problem = problem;
        Line = line;
        Column = column;
        ByteOffset = byteOffset;
    }

    public string FileName { get; }

    public string Problem { get; }

    /// <summary>1-based line of text formats.</summary>
    public int? Line { get; }

    /// <summary>1-based column within <see cref="Line"/>, when known.</summary>
    public int? Column { get; }

    /// <summary>Offset from the start of the file in binary formats.</summary>
    public long? ByteOffset { get; }

    private static string Format(string fileName, string problem, int? line, long? byteOffset, int? column) =>
        line is { } l ? (column is { } c ? $"{fileName}({l},{c}): {problem}" : $"{fileName}({l}): {problem}")
        : byteOffset is { } b ? $"{fileName} (byte {b}): {problem}"
        : $"{fileName}: {problem}";
}
