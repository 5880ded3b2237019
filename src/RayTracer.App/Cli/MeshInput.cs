using RayTracer.Geometry.Meshes;

namespace RayTracer.Cli;

/// <summary>Reads a mesh file named on the command line, reporting its warnings and errors as <c>FILE(LINE,COL): KIND: ...</c>.</summary>
internal static class MeshInput
{
    /// <summary>The mesh, or null after writing why it cannot be used.</summary>
    public static Mesh? Read(string path, TextWriter stderr)
    {
        Mesh mesh;
        try
        {
            using var stream = File.OpenRead(path);
            // The readers name the file in their messages as given here: the path the user typed.
            mesh = Path.GetExtension(path).Equals(".stl", StringComparison.OrdinalIgnoreCase)
                ? StlReader.Read(stream, path)
                : PlyReader.Read(stream, path);
        }
        catch (MeshFormatException e)
        {
            stderr.WriteLine(WithKind(e.Message, path, "error"));
            return null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"{path}: error: cannot read the file: {e.Message}");
            return null;
        }

        foreach (var warning in mesh.Warnings)
            stderr.WriteLine(WithKind(warning, path, "warning"));
        if (mesh.TriangleCount == 0)
        {
            stderr.WriteLine($"{path}: error: the mesh has no triangles");
            return null;
        }
        return mesh;
    }

    /// <summary>Turns a reader's <c>FILE(LINE): text</c> into <c>FILE(LINE): kind: text</c>, the form compilers use.</summary>
    private static string WithKind(string message, string path, string kind)
    {
        var split = message.StartsWith(path, StringComparison.Ordinal) ? message.IndexOf(": ", path.Length, StringComparison.Ordinal) : -1;
        return split < 0 ? $"{path}: {kind}: {message}" : $"{message[..split]}: {kind}: {message[(split + 2)..]}";
    }
}
