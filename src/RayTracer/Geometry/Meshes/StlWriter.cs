using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using RayTracer.Kernels;
using RayTracer.Maths;
using SafeFiles;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Writes a mesh as STL. ASCII files carry full double precision; binary STL stores 32-bit floats
/// by definition. Facet normals are the unit face normals.
/// </summary>
public static class StlWriter
{
    public static void Write(Mesh mesh, string path, StlFormat format) =>
        OutputFile.Write(path, stream => Write(mesh, stream, format));

    public static void Write(Mesh mesh, Stream stream, StlFormat format)
    {
        ArgumentNullException.ThrowIfNull(mesh);
        ArgumentNullException.ThrowIfNull(stream);
        if (format == StlFormat.Ascii)
        {
            WriteAscii(mesh, stream);
        }
        else
        {
            WriteBinary(mesh, stream);
        }
    }

    private static Vector3D FaceNormal(Mesh mesh, int f, out Point3D a, out Point3D b, out Point3D c)
    {
        a = mesh.Vertices[mesh.Indices[3 * f]];
        b = mesh.Vertices[mesh.Indices[3 * f + 1]];
        c = mesh.Vertices[mesh.Indices[3 * f + 2]];
        var n = TriangleNormal.Of(a, b, c).ToVector();
        double len = n.Length;
        return len > 0 ? n / len : Vector3D.Zero;
    }

    private static void WriteAscii(Mesh mesh, Stream stream)
    {
        using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true) { NewLine = "\n" };
        writer.WriteLine("solid mesh");
        for (int f = 0; f < mesh.TriangleCount; f++)
        {
            var n = FaceNormal(mesh, f, out var a, out var b, out var c);
            writer.WriteLine($"  facet normal {N(n.x)} {N(n.y)} {N(n.z)}");
            writer.WriteLine("    outer loop");
            writer.WriteLine($"      vertex {N(a.x)} {N(a.y)} {N(a.z)}");
            writer.WriteLine($"      vertex {N(b.x)} {N(b.y)} {N(b.z)}");
            writer.WriteLine($"      vertex {N(c.x)} {N(c.y)} {N(c.z)}");
            writer.WriteLine("    endloop");
            writer.WriteLine("  endfacet");
        }

        writer.WriteLine("endsolid mesh");
    }

    private static string N(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static void WriteBinary(Mesh mesh, Stream stream)
    {
        var header = new byte[84];
        Encoding.ASCII.GetBytes("binary STL").CopyTo(header, 0);
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(80), (uint)mesh.TriangleCount);
        stream.Write(header);

        var record = new byte[50];
        for (int f = 0; f < mesh.TriangleCount; f++)
        {
            var n = FaceNormal(mesh, f, out var a, out var b, out var c);
            Span<byte> s = record;
            PutVector(s, 0, n.x, n.y, n.z);
            PutVector(s, 12, a.x, a.y, a.z);
            PutVector(s, 24, b.x, b.y, b.z);
            PutVector(s, 36, c.x, c.y, c.z);
            record[48] = record[49] = 0;
            stream.Write(record);
        }
    }

    private static void PutVector(Span<byte> s, int at, double x, double y, double z)
    {
        BinaryPrimitives.WriteSingleLittleEndian(s[at..], (float)x);
        BinaryPrimitives.WriteSingleLittleEndian(s[(at + 4)..], (float)y);
        BinaryPrimitives.WriteSingleLittleEndian(s[(at + 8)..], (float)z);
    }
}
