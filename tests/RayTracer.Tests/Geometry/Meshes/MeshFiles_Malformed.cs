using System.Text;
using RayTracer.Geometry.Meshes;

namespace RayTracer.Tests.Geometry.Meshes;

public class MeshFiles_Malformed
{
    private static MeshFormatException ReadPly(string text) =>
        Assert.Throws<MeshFormatException>(() => PlyReader.Read(new MemoryStream(Encoding.ASCII.GetBytes(text)), "bad.ply"));

    private const string Header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

    [Fact]
    public void Missing_magic_is_reported_on_line_one()
    {
        var e = ReadPly("plx\nformat ascii 1.0\n");
        Assert.Equal(1, e.Line);
        Assert.Equal("bad.ply", e.FileName);
        Assert.StartsWith("bad.ply(1):", e.Message);
    }

    [Fact]
    public void Unknown_property_type_is_reported_on_its_line()
    {
        var e = ReadPly("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n");
        Assert.Equal(4, e.Line);
        Assert.Contains("quad", e.Message);
    }

    [Fact]
    public void Bad_number_in_the_body_names_its_line()
    {
        var e = ReadPly(Header + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n");
        Assert.Equal(11, e.Line);
        Assert.Contains("zero", e.Message);
    }

    [Fact]
    public void Out_of_range_index_is_rejected()
    {
        var e = ReadPly(Header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
        Assert.Equal(13, e.Line);
        Assert.Contains("vertex 3", e.Message);
    }

    [Fact]
    public void Truncated_ascii_body_is_reported()
    {
        var e = ReadPly(Header + "0 0 0\n1 0 0\n0 1");
        Assert.Contains("ends inside vertex 2", e.Message);
    }

    [Fact]
    public void Absurd_declared_counts_fail_on_the_truncated_body_not_on_memory()
    {
        string header = "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
        byte[] bytes = [.. Encoding.ASCII.GetBytes(header), .. new byte[30]];
        var e = Assert.Throws<MeshFormatException>(() => PlyReader.Read(new ForwardOnlyStream(bytes), "huge.ply"));
        Assert.Contains("vertex 1", e.Message);
        Assert.Equal(bytes.Length, e.ByteOffset);
    }

    [Fact]
    public void Missing_end_header_is_reported()
    {
        var e = ReadPly("ply\nformat ascii 1.0\nelement vertex 0\n");
        Assert.Contains("end_header", e.Message);
    }

    [Fact]
    public void Truncated_binary_ply_gives_the_byte_offset()
    {
        using var stream = new MemoryStream();
        PlyWriter.Write(MeshSamples.Octahedron(false), stream, PlyFormat.BinaryLittleEndian);
        byte[] bytes = stream.ToArray();
        int headerLength = Encoding.ASCII.GetString(bytes).IndexOf("end_header\n", StringComparison.Ordinal) + "end_header\n".Length;
        // Cut inside the z coordinate of vertex 2: 2 vertices of 24 bytes, plus 16 bytes, plus 3 more.
        int cut = headerLength + 2 * 24 + 16 + 3;
        // Read as a pipe, the reader only finds out at the cut.
        var e = Assert.Throws<MeshFormatException>(() => PlyReader.Read(new ForwardOnlyStream(bytes[..cut]), "cut.ply"));
        Assert.Equal(cut, e.ByteOffset);
        Assert.Contains("vertex 2", e.Message);
        Assert.Null(e.Line);

        // Knowing the length, it refuses the vertices before reading them.
        e = Assert.Throws<MeshFormatException>(() => PlyReader.Read(new MemoryStream(bytes[..cut]), "cut.ply"));
        Assert.Equal(headerLength, e.ByteOffset);
        Assert.Contains($"element 'vertex' declares 6 items of at least 24 bytes, but only {cut - headerLength} bytes remain", e.Message);
    }

    [Fact]
    public void Truncated_binary_stl_gives_the_byte_offset_and_triangle()
    {
        using var stream = new MemoryStream();
        StlWriter.Write(MeshSamples.FloatExactSoup(10, 1), stream, StlFormat.Binary);
        byte[] bytes = stream.ToArray()[..(84 + 50 * 6 + 20)];
        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(bytes), "cut.stl"));
        Assert.Equal(bytes.Length, e.ByteOffset);
        Assert.Contains("triangle 6", e.Message);
    }

    [Fact]
    public void Malformed_ascii_stl_names_the_line()
    {
        const string text = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 oops\n  endloop\n endfacet\nendsolid x\n";
        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(Encoding.ASCII.GetBytes(text)), "bad.stl"));
        Assert.Equal(6, e.Line);
        Assert.Contains("oops", e.Message);
    }

    [Fact]
    public void Ascii_stl_without_endsolid_is_reported()
    {
        const string text = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n";
        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(Encoding.ASCII.GetBytes(text)), "bad.stl"));
        Assert.Contains("end of file", e.Message);
    }

    [Fact]
    public void A_binary_stl_whose_header_starts_with_solid_is_reported_as_binary()
    {
        using var stream = new MemoryStream();
        StlWriter.Write(MeshSamples.FloatExactSoup(4, 1), stream, StlFormat.Binary);
        byte[] bytes = stream.ToArray();
        Encoding.ASCII.GetBytes("solid exported by a CAD tool").CopyTo(bytes, 0);
        bytes[80] = 5;

        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(bytes), "solid.stl"));

        // 4 triangles are there, 5 are declared: the file ends inside the fifth.
        Assert.Equal(bytes.Length, e.ByteOffset);
        Assert.Contains("binary STL declares 5 triangles (334 bytes) but the file ends inside triangle 4", e.Message);
        Assert.Contains("header starts with 'solid'", e.Message);
    }

    [Fact]
    public void Ascii_stl_without_solid_is_reported_as_ascii_at_its_first_word()
    {
        const string text = "\n  facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid x\n";

        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(Encoding.ASCII.GetBytes(text)), "nosolid.stl"));

        Assert.Equal(2, e.Line);
        Assert.Equal(3, e.Column);
        Assert.Contains("an ASCII STL file starts with 'solid', found 'facet'", e.Message);
        Assert.DoesNotContain("binary", e.Message.Replace("not binary STL", "", StringComparison.Ordinal));
    }

    [Fact]
    public void Ascii_stl_may_start_with_a_byte_order_mark()
    {
        const string text = "\uFEFFsolid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid x\n";

        var mesh = StlReader.Read(new MemoryStream(Encoding.UTF8.GetBytes(text)), "bom.stl");

        Assert.Equal(1, mesh.TriangleCount);
    }

    [Fact]
    public void Ascii_stl_errors_name_the_column()
    {
        const string text = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 oops\n  endloop\n endfacet\nendsolid x\n";

        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(Encoding.ASCII.GetBytes(text)), "bad.stl"));

        Assert.Equal((6, 15), (e.Line, e.Column));
        Assert.StartsWith("bad.stl(6,15): 'oops' is not a number", e.Message);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void A_ply_list_length_of_uint_max_is_reported_as_a_list_length(bool asPipe)
    {
        string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" +
            "element face 1\nproperty list uint int vertex_indices\nend_header\n";
        var body = new byte[9 * 4 + 4 + 12];
        BitConverter.GetBytes(1f).CopyTo(body, 12);
        BitConverter.GetBytes(1f).CopyTo(body, 28);
        BitConverter.GetBytes(uint.MaxValue).CopyTo(body, 36);
        byte[] bytes = [.. Encoding.ASCII.GetBytes(header), .. body];
        Stream stream = asPipe ? new ForwardOnlyStream(bytes) : new MemoryStream(bytes);

        var e = Assert.Throws<MeshFormatException>(() => PlyReader.Read(stream, "list.ply"));

        Assert.Equal(bytes.Length - 12, e.ByteOffset);
        Assert.Contains("a list in face 0 declares 4294967295 items", e.Message);
        Assert.DoesNotContain("expected an integer", e.Message);
    }

    [Fact]
    public void A_ply_vertex_index_of_uint_max_is_reported_as_an_index()
    {
        string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" +
            "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
        var body = new byte[9 * 4 + 1 + 12];
        body[36] = 3;
        BitConverter.GetBytes(uint.MaxValue).CopyTo(body, 37 + 8);
        byte[] bytes = [.. Encoding.ASCII.GetBytes(header), .. body];

        var e = Assert.Throws<MeshFormatException>(() => PlyReader.Read(new MemoryStream(bytes), "index.ply"));

        Assert.Contains("face 0 refers to vertex 4294967295, but there are 3 vertices", e.Message);
    }

    [Fact]
    public void Garbage_that_is_neither_format_is_rejected()
    {
        var e = Assert.Throws<MeshFormatException>(() => StlReader.Read(new MemoryStream(new byte[40]), "tiny.stl"));
        Assert.Equal("tiny.stl", e.FileName);
    }
}
