using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using SafeFiles;

namespace RayTracer.Geometry.Meshes;

/// <summary>
/// Writes a mesh as PLY: double-precision vertex properties (so ASCII and binary files round-trip
/// exactly), optional normals and (u, v), and triangles as lists of int indices.
/// </summary>
public static class PlyWriter
{
    public static void Write(Mesh mesh, string path, PlyFormat format) =>
        OutputFile.Write(path, stream => Write(mesh, stream, format));

    public static void Write(Mesh mesh, Stream stream, PlyFormat format)
    {
        ArgumentNullException.ThrowIfNull(mesh);
        ArgumentNullException.ThrowIfNull(stream);
        bool normals = mesh.Normals is not null, uvs = mesh.TextureCoordinates is not null;

        var header = new StringBuilder();
        header.Append("ply\n");
        header.Append(format switch
        {
            PlyFormat.Ascii => "format ascii 1.0\n",
            PlyFormat.BinaryLittleEndian => "format binary_little_endian 1.0\n",
            _ => "format binary_big_endian 1.0\n",
        });
        header.Append(CultureInfo.InvariantCulture, $"element vertex {mesh.Vertices.Length}\n");
        header.Append("property double x\nproperty double y\nproperty double z\n");
        if (normals)
        {
            header.Append("property double nx\nproperty double ny\nproperty double nz\n");
        }

        if (uvs)
        {
            header.Append("property double u\nproperty double v\n");
        }

        header.Append(CultureInfo.InvariantCulture, $"element face {mesh.TriangleCount}\n");
        header.Append("property list uchar int vertex_indices\nend_header\n");
        byte[] headerBytes = Encoding.ASCII.GetBytes(header.ToString());
        stream.Write(headerBytes);

        if (format == PlyFormat.Ascii)
        {
            WriteAscii(mesh, stream, normals, uvs);
        }
        else
        {
            WriteBinary(mesh, stream, normals, uvs, format == PlyFormat.BinaryLittleEndian);
        }
    }

    private static void WriteAscii(Mesh mesh, Stream stream, bool normals, bool uvs)
    {
        using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true) { NewLine = "\n" };
        var line = new StringBuilder();
        for (int i = 0; i < mesh.Vertices.Length; i++)
        {
            line.Clear();
            var p = mesh.Vertices[i];
            Append(line, p.x, p.y, p.z);
            if (normals)
            {
                var n = mesh.Normals![i];
                line.Append(' ');
                Append(line, n.x, n.y, n.z);
            }

            if (uvs)
            {
                var uv = mesh.TextureCoordinates![i];
                line.Append(' ');
                line.Append(uv.u.ToString("R", CultureInfo.InvariantCulture)).Append(' ')
                    .Append(uv.v.ToString("R", CultureInfo.InvariantCulture));
            }

            writer.WriteLine(line);
        }

        for (int f = 0; f < mesh.TriangleCount; f++)
        {
            writer.WriteLine(string.Create(
                CultureInfo.InvariantCulture, $"3 {mesh.Indices[3 * f]} {mesh.Indices[3 * f + 1]} {mesh.Indices[3 * f + 2]}"));
        }
    }

    private static void Append(StringBuilder line, double x, double y, double z) =>
        line.Append(x.ToString("R", CultureInfo.InvariantCulture)).Append(' ')
            .Append(y.ToString("R", CultureInfo.InvariantCulture)).Append(' ')
            .Append(z.ToString("R", CultureInfo.InvariantCulture));

    private static void WriteBinary(Mesh mesh, Stream stream, bool normals, bool uvs, bool little)
    {
        int stride = 8 * (3 + (normals ? 3 : 0) + (uvs ? 2 : 0));
        var buffer = new byte[Math.Max(stride, 13)];
        for (int i = 0; i < mesh.Vertices.Length; i++)
        {
            var p = mesh.Vertices[i];
            int at = 0;
            Put(buffer, ref at, p.x, little);
            Put(buffer, ref at, p.y, little);
            Put(buffer, ref at, p.z, little);
            if (normals)
            {
                var n = mesh.Normals![i];
                Put(buffer, ref at, n.x, little);
                Put(buffer, ref at, n.y, little);
                Put(buffer, ref at, n.z, little);
            }

            if (uvs)
            {
                var uv = mesh.TextureCoordinates![i];
                Put(buffer, ref at, uv.u, little);
                Put(buffer, ref at, uv.v, little);
            }

            stream.Write(buffer, 0, at);
        }

        for (int f = 0; f < mesh.TriangleCount; f++)
        {
            buffer[0] = 3;
            for (int k = 0; k < 3; k++)
            {
                var slot = buffer.AsSpan(1 + 4 * k, 4);
                if (little)
                {
                    BinaryPrimitives.WriteInt32LittleEndian(slot, mesh.Indices[3 * f + k]);
                }
                else
                {
                    BinaryPrimitives.WriteInt32BigEndian(slot, mesh.Indices[3 * f + k]);
                }
            }

            stream.Write(buffer, 0, 13);
        }
    }

    private static void Put(byte[] buffer, ref int at, double value, bool little)
    {
        if (little)
        {
            BinaryPrimitives.WriteDoubleLittleEndian(buffer.AsSpan(at, 8), value);
        }
        else
        {
            BinaryPrimitives.WriteDoubleBigEndian(buffer.AsSpan(at, 8), value);
        }

        at += 8;
    }
}
