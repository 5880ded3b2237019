namespace RayTracer.Geometry.Meshes;

/// <summary>Reads and writes meshes choosing PLY or STL by the file extension.</summary>
public static class MeshFile
{
    public static Mesh Read(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        return Path.GetExtension(path).ToLowerInvariant() switch
        {
            ".ply" => PlyReader.Read(path),
            ".stl" => StlReader.Read(path),
            string other => throw new MeshFormatException(
                Path.GetFileName(path), $"unknown mesh file extension '{other}' (expected .ply or .stl)"),
        };
    }

    /// <summary>Writes binary PLY or binary STL, or their ASCII forms when <paramref name="ascii"/> is set.</summary>
    public static void Write(Mesh mesh, string path, bool ascii = false)
    {
        ArgumentNullException.ThrowIfNull(path);
        switch (Path.GetExtension(path).ToLowerInvariant())
        {
            case ".ply":
                PlyWriter.Write(mesh, path, ascii ? PlyFormat.Ascii : PlyFormat.BinaryLittleEndian);
                break;
            case ".stl":
                StlWriter.Write(mesh, path, ascii ? StlFormat.Ascii : StlFormat.Binary);
                break;
            default:
                throw new ArgumentException($"Unknown mesh file extension in '{path}' (expected .ply or .stl).", nameof(path));
        }
    }
}
