using RayTracer.Geometry.Meshes;

namespace RayTracer.Tests.Geometry.Meshes;

public class MeshFiles_RoundTrip
{
    private static void AssertSameMesh(Mesh expected, Mesh actual)
    {
        Assert.Equal(expected.Vertices, actual.Vertices);
        Assert.Equal(expected.Indices, actual.Indices);
        Assert.Equal(expected.Normals, actual.Normals);
        Assert.Equal(expected.TextureCoordinates, actual.TextureCoordinates);
    }

    [Theory]
    [InlineData(PlyFormat.Ascii)]
    [InlineData(PlyFormat.BinaryLittleEndian)]
    [InlineData(PlyFormat.BinaryBigEndian)]
    public void Ply_round_trips_exactly(PlyFormat format)
    {
        foreach (bool attributes in new[] { false, true })
        {
            var mesh = MeshSamples.Octahedron(attributes);
            // Coordinates with many significant digits, to check nothing is rounded.
            for (int i = 0; i < mesh.Vertices.Length; i++)
            {
                mesh.Vertices[i].x += Math.PI * 1e-3 * i;
            }

            using var stream = new MemoryStream();
            PlyWriter.Write(mesh, stream, format);
            stream.Position = 0;
            AssertSameMesh(mesh, PlyReader.Read(stream, "octahedron.ply"));
        }
    }

    [Fact]
    public void Ply_through_a_file_on_disk()
    {
        string dir = Directory.CreateTempSubdirectory("rt-ply").FullName;
        try
        {
            string path = Path.Combine(dir, "mesh.ply");
            var mesh = MeshSamples.FloatExactSoup(50, 3);
            PlyWriter.Write(mesh, path, PlyFormat.BinaryLittleEndian);
            AssertSameMesh(mesh, PlyReader.Read(path));
            Assert.Single(Directory.GetFiles(dir)); // no temporary file left behind
        }
        finally
        {
            Directory.Delete(dir, true);
        }
    }

    [Theory]
    [InlineData("mesh.ply", false)]
    [InlineData("mesh.PLY", true)]
    [InlineData("mesh.stl", false)]
    [InlineData("mesh.stl", true)]
    public void Mesh_file_dispatches_on_the_extension(string name, bool ascii)
    {
        string dir = Directory.CreateTempSubdirectory("rt-mesh").FullName;
        try
        {
            string path = Path.Combine(dir, name);
            var mesh = MeshSamples.FloatExactSoup(20, 9);
            MeshFile.Write(mesh, path, ascii);
            var read = MeshFile.Read(path);
            Assert.Equal(mesh.TriangleCount, read.TriangleCount);
            for (int i = 0; i < mesh.Indices.Length; i++)
            {
                Assert.Equal(mesh.Vertices[mesh.Indices[i]], read.Vertices[read.Indices[i]]);
            }

            Assert.Throws<MeshFormatException>(() => MeshFile.Read(Path.ChangeExtension(path, ".obj")));
        }
        finally
        {
            Directory.Delete(dir, true);
        }
    }

    [Fact]
    public void Ply_reader_splits_polygons_and_skips_unknown_elements()
    {
        const string text = """
            ply
            format ascii 1.0
            comment a quad and a pentagon with extra data
            element vertex 6
            property float x
            property float y
            property float z
            property uchar red
            element face 2
            property list uchar int vertex_indices
            property int flags
            element edge 1
            property int vertex1
            property int vertex2
            end_header
            0 0 0 255
            1 0 0 255
            1 1 0 255
            0 1 0 255
            0.5 2 0 255
            2 2 2 0
            4 0 1 2 3 7
            5 0 1 2 4 3 9
            0 1
            """;
        var mesh = PlyReader.Read(new MemoryStream(System.Text.Encoding.ASCII.GetBytes(text)), "poly.ply");
        Assert.Equal(6, mesh.Vertices.Length);
        Assert.Equal(2 + 3, mesh.TriangleCount);
        Assert.Equal(new[] { 0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 4, 0, 4, 3 }, mesh.Indices);
    }

    [Fact]
    public void Stl_ascii_round_trips_exactly()
    {
        var mesh = MeshSamples.Octahedron(false);
        using var stream = new MemoryStream();
        StlWriter.Write(mesh, stream, StlFormat.Ascii);
        stream.Position = 0;
        var read = StlReader.Read(stream, "octahedron.stl");
        // Corners shared between facets are merged back into six vertices in first-use order.
        Assert.Equal(6, read.Vertices.Length);
        Assert.Equal(mesh.TriangleCount, read.TriangleCount);
        for (int i = 0; i < mesh.Indices.Length; i++)
        {
            Assert.Equal(mesh.Vertices[mesh.Indices[i]], read.Vertices[read.Indices[i]]);
        }
    }

    [Fact]
    public void Stl_binary_round_trips_float_coordinates()
    {
        var mesh = MeshSamples.FloatExactSoup(200, 7);
        using var stream = new MemoryStream();
        StlWriter.Write(mesh, stream, StlFormat.Binary);
        Assert.Equal(84 + 50 * 200, stream.Length);
        stream.Position = 0;
        var read = StlReader.Read(stream, "soup.stl");
        Assert.Equal(mesh.TriangleCount, read.TriangleCount);
        for (int i = 0; i < mesh.Indices.Length; i++)
        {
            Assert.Equal(mesh.Vertices[mesh.Indices[i]], read.Vertices[read.Indices[i]]);
        }
    }

    [Fact]
    public void Binary_stl_whose_header_starts_with_solid_is_still_binary()
    {
        var mesh = MeshSamples.FloatExactSoup(3, 8);
        using var stream = new MemoryStream();
        StlWriter.Write(mesh, stream, StlFormat.Binary);
        byte[] bytes = stream.ToArray();
        "solid but binary"u8.CopyTo(bytes);
        var read = StlReader.Read(new MemoryStream(bytes), "tricky.stl");
        Assert.Equal(3, read.TriangleCount);
    }
}
