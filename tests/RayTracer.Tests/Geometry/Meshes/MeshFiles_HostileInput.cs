using System.Buffers.Binary;
using System.Text;
using RayTracer.Geometry.Meshes;

namespace RayTracer.Tests.Geometry.Meshes;

public class MeshFiles_HostileInput
{
    private const string Huge = "1000000000000000000";

    private const string TriangleHeader =
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n";

    /// <summary>Binary little-endian PLY: the header lines, then the three vertices and one face of a triangle, then <paramref name="tail"/>.</summary>
    private static byte[] BinaryPly(string headerLines, float[]? coordinates = null, params byte[] tail)
    {
        string header = "ply\nformat binary_little_endian 1.0\n" + headerLines + "end_header\n";
        var body = new List<byte>();
        foreach (float c in coordinates ?? [0, 0, 0, 1, 0, 0, 0, 1, 0])
        {
            body.AddRange(BitConverter.GetBytes(c));
        }

        body.Add(3);
        foreach (int i in new[] { 0, 1, 2 })
        {
            body.AddRange(BitConverter.GetBytes(i));
        }

        return [.. Encoding.ASCII.GetBytes(header), .. body, .. tail];
    }

    private static Mesh Read(byte[] bytes, string name = "hostile.ply") => PlyReader.Read(new MemoryStream(bytes), name);

    private static MeshFormatException Fails(byte[] bytes, string name = "hostile.ply") =>
        Assert.Throws<MeshFormatException>(() => Read(bytes, name));

    private static MeshFormatException FailsAscii(string text) => Fails(Encoding.ASCII.GetBytes(text));

    [Theory]
    [InlineData("binary_little_endian")]
    [InlineData("ascii")]
    public async Task An_element_without_properties_and_a_huge_count_is_skipped_at_once(string format)
    {
        // Such an element holds no data at all; counting through 10^18 of them used to spin for years.
        string text = $"ply\nformat {format} 1.0\nelement nothing {Huge}\nelement vertex 3\nproperty uchar x\nproperty uchar y\nproperty uchar z\n" +
            "element face 1\nproperty list uchar uchar vertex_indices\nend_header\n";
        byte[] body = format == "ascii" ? Encoding.ASCII.GetBytes("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") : [0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2];
        byte[] bytes = [.. Encoding.ASCII.GetBytes(text), .. body];

        // The time limit is only a safety net against a hang.
        var mesh = await Task.Run(() => Read(bytes)).WaitAsync(TimeSpan.FromSeconds(30));
        Assert.Equal(1, mesh.TriangleCount);
    }

    [Fact]
    public void A_binary_count_larger_than_the_rest_of_the_file_fails_before_reading_it()
    {
        byte[] bytes = BinaryPly(TriangleHeader + $"element edge {Huge}\nproperty int vertex1\nproperty int vertex2\n", null, new byte[16]);
        int edgesStart = bytes.Length - 16;

        var e = Fails(bytes);

        Assert.Equal(edgesStart, e.ByteOffset);
        Assert.Contains($"element 'edge' declares {Huge} items of at least 8 bytes, but only 16 bytes remain", e.Message);
    }

    [Fact]
    public void An_element_of_lists_only_is_checked_by_its_length_prefixes()
    {
        byte[] bytes = BinaryPly(TriangleHeader + "element material 4000\nproperty list ushort uchar name\n", null, new byte[10]);

        var e = Fails(bytes);

        Assert.Equal(bytes.Length - 10, e.ByteOffset);
        Assert.Contains("element 'material' declares 4000 items of at least 2 bytes, but only 10 bytes remain", e.Message);
    }

    [Fact]
    public void A_list_longer_than_the_rest_of_the_file_fails_at_its_length()
    {
        var tail = new byte[12];
        BinaryPrimitives.WriteInt32LittleEndian(tail, 2_000_000_000);
        byte[] bytes = BinaryPly(TriangleHeader + "element material 1\nproperty list int uchar name\n", null, tail);

        var e = Fails(bytes);

        Assert.Equal(bytes.Length - 8, e.ByteOffset);
        Assert.Contains("material 0 declares 2000000000 items, but only 8 bytes remain", e.Message);
    }

    [Fact]
    public void A_huge_ascii_count_fails_at_the_end_of_the_file()
    {
        string text = "ply\nformat ascii 1.0\n" + TriangleHeader + $"element edge {Huge}\nproperty int vertex1\nend_header\n" +
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n8\n";

        var e = FailsAscii(text);

        Assert.Contains("ends inside edge 2", e.Message);
        Assert.Equal(18, e.Line);
    }

    [Theory]
    [InlineData("nan", "x")]
    [InlineData("-Infinity", "x")]
    [InlineData("1e999", "x")]
    public void A_non_finite_ascii_vertex_is_rejected_with_its_index_and_line(string value, string axis)
    {
        string text = "ply\nformat ascii 1.0\n" + TriangleHeader + "end_header\n0 0 0\n" + value + " 0 0\n0 1 0\n3 0 1 2\n";

        var e = FailsAscii(text);

        Assert.Equal(11, e.Line);
        Assert.Contains($"vertex 1 has a non-finite {axis}", e.Message);
    }

    [Fact]
    public void A_non_finite_binary_vertex_is_rejected_with_its_index_and_offset()
    {
        byte[] bytes = BinaryPly(TriangleHeader, [0, 0, 0, 1, 0, 0, 0, 1, float.PositiveInfinity]);
        int bodyStart = bytes.Length - 9 * 4 - 13;

        var e = Fails(bytes);

        Assert.Equal(bodyStart + 8 * 4, e.ByteOffset);
        Assert.Contains("vertex 2 has a non-finite z", e.Message);
    }

    [Fact]
    public void A_non_finite_binary_stl_vertex_is_rejected_with_its_triangle_and_offset()
    {
        using var stream = new MemoryStream();
        StlWriter.Write(MeshSamples.FloatExactSoup(4, 1), stream, StlFormat.Binary);
        byte[] bytes = stream.ToArray();
        // Triangle 2 starts at 84 + 2·50; its corners follow the 12-byte facet normal; y of corner 1.
        int at = 84 + 2 * 50 + 12 + 12 * 1 + 4;
        BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(at), float.NaN);

        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(bytes), "nan.stl"));

        Assert.Equal(at, e.ByteOffset);
        Assert.Contains("triangle 2 vertex 1 has a non-finite y", e.Message);
    }

    [Fact]
    public void A_non_finite_ascii_stl_vertex_is_rejected_with_its_facet_and_line()
    {
        const string text = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n" +
            " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 Infinity 0\n  endloop\n endfacet\nendsolid x\n";

        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(Encoding.ASCII.GetBytes(text)), "inf.stl"));

        Assert.Equal(13, e.Line);
        Assert.Contains("facet 1 vertex 2 has a non-finite y", e.Message);
    }

    private static byte[] BinaryStl(int triangles)
    {
        using var stream = new MemoryStream();
        StlWriter.Write(MeshSamples.FloatExactSoup(triangles, 1), stream, StlFormat.Binary);
        return stream.ToArray();
    }

    [Fact]
    public void An_endless_binary_stl_is_read_no_further_than_its_declared_triangles()
    {
        byte[] stl = BinaryStl(3);
        var endless = new EndlessStream(stl, limit: 64 << 20);

        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(endless, "endless.stl"));

        Assert.Equal(stl.Length, e.ByteOffset);
        Assert.Contains("binary STL declares 3 triangles (234 bytes) but the file goes on after them", e.Message);
        // One read buffer, not the stream: memory follows the triangles, not what the file holds.
        Assert.True(endless.BytesRead <= 1 << 16, $"{endless.BytesRead} bytes read");
    }

    [Fact]
    public void A_link_to_dev_zero_is_a_clear_error()
    {
        if (!File.Exists("/dev/zero"))
        {
            return;
        }

        var link = Path.Combine(Path.GetTempPath(), Guid.NewGuid().ToString("N") + "-zero.stl");
        File.CreateSymbolicLink(link, "/dev/zero");
        try
        {
            var e = Assert.Throws<MeshFormatException>(() => MeshFile.Read(link));
            Assert.Equal(84, e.ByteOffset);
            Assert.Contains("declares 0 triangles (84 bytes) but the file goes on after them", e.Message);
        }
        finally
        {
            File.Delete(link);
        }
    }

    [Fact]
    public void A_huge_sparse_stl_is_refused_by_its_size_without_reading_it()
    {
        var path = Path.Combine(Path.GetTempPath(), Guid.NewGuid().ToString("N") + "-sparse.stl");
        using (var file = File.Create(path))
        {
            // 3 GB of zeros that take no disk space: its header declares no triangles.
            file.SetLength(3L << 30);
        }

        try
        {
            var e = Assert.Throws<MeshFormatException>(() => MeshFile.Read(path));
            Assert.Equal(84, e.ByteOffset);
            Assert.Contains($"binary STL declares 0 triangles (84 bytes) but the file has {3L << 30} bytes", e.Message);
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Theory]
    [InlineData("empty.ply")]
    [InlineData("empty.stl")]
    public void An_empty_file_is_reported_at_line_1_column_1(string name)
    {
        var path = Path.Combine(Path.GetTempPath(), Guid.NewGuid().ToString("N") + "-" + name);
        File.WriteAllBytes(path, []);
        try
        {
            var e = Assert.Throws<MeshFormatException>(() => MeshFile.Read(path));
            Assert.Equal(1, e.Line);
            Assert.Equal(1, e.Column);
            Assert.StartsWith($"{Path.GetFileName(path)}(1,1): the file is empty", e.Message);
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public void An_unknown_header_line_is_skipped_with_a_warning()
    {
        // Blender 2.47 wrote this line without the 'comment' keyword.
        string text = "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org, source file: 'cube.blend'\n" + TriangleHeader +
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

        var mesh = Read(Encoding.ASCII.GetBytes(text), "blender.ply");

        Assert.Equal(1, mesh.TriangleCount);
        string warning = Assert.Single(mesh.Warnings);
        Assert.StartsWith("blender.ply(3):", warning);
        Assert.Contains("Created by Blender3D 247", warning);
    }

    [Fact]
    public void A_clean_file_has_no_warnings()
    {
        Assert.Empty(Read(BinaryPly(TriangleHeader)).Warnings);
    }
}
