using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Universal;
using RayTracer.Kernels;
using RayTracer.Maths;
using RayTracer.Randomness;
using RayTracer.Tracing;

namespace RayTracer.Tests.Kernels;

public class TriangleNormal_CrossProduct
{
    private const double Tolerance = 1e-12;

    private static IEnumerable<(Point3D V0, Point3D V1, Point3D V2)> RandomTriangles(int count)
    {
        var random = new SeededRandom(41);
        for (var i = 0; i < count; i++)
        {
            // Scales from 1e-3 to 1e3 and offsets away from the origin, as meshes have.
            var scale = Math.Pow(10, random.NextDouble(-3, 3));
            var offset = new Vector3D(random.NextDouble(-50, 50), random.NextDouble(-50, 50), random.NextDouble(-50, 50));
            Point3D Vertex() => new Point3D(random.NextDouble(-1, 1), random.NextDouble(-1, 1), random.NextDouble(-1, 1)) * scale + offset;
            yield return (Vertex(), Vertex(), Vertex());
        }
    }

    /// <summary>(v1 − v0) × (v2 − v0) written out component by component.</summary>
    private static (double X, double Y, double Z) EdgeCross(Point3D v0, Point3D v1, Point3D v2)
    {
        double ux = v1.x - v0.x, uy = v1.y - v0.y, uz = v1.z - v0.z;
        double vx = v2.x - v0.x, vy = v2.y - v0.y, vz = v2.z - v0.z;
        return (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
    }

    private static void AssertClose((double X, double Y, double Z) expected, Normal3D actual)
    {
        var size = Math.Sqrt(expected.X * expected.X + expected.Y * expected.Y + expected.Z * expected.Z);
        var error = Math.Sqrt(Math.Pow(actual.x - expected.X, 2) + Math.Pow(actual.y - expected.Y, 2) + Math.Pow(actual.z - expected.Z, 2));
        Assert.True(error <= Tolerance * size, $"normal {actual} differs from {expected} by {error / size:E2} relative");
    }

    [Fact]
    public void Generated_normal_equals_the_cross_product_of_the_edges_on_random_triangles()
    {
        foreach (var (v0, v1, v2) in RandomTriangles(2000))
        {
            var n = TriangleNormal.Of(v0, v1, v2);
            AssertClose(EdgeCross(v0, v1, v2), n);

            // Independent of any formula: the normal is orthogonal to both edges and |n| = |u| |v| sin θ.
            var u = v1 - v0;
            var v = v2 - v0;
            var cos = u.Dot(v) / (u.Length * v.Length);
            Assert.Equal(u.Length * v.Length * Math.Sqrt(1 - cos * cos), n.Length, n.Length * 1e-6);
            Assert.True(Math.Abs(n.Dot(u)) <= 1e-12 * n.Length * u.Length);
            Assert.True(Math.Abs(n.Dot(v)) <= 1e-12 * n.Length * v.Length);
        }
    }

    [Fact]
    public void Universal_and_mesh_triangles_take_their_face_normal_from_the_edges()
    {
        foreach (var (v0, v1, v2) in RandomTriangles(200))
        {
            var (x, y, z) = EdgeCross(v0, v1, v2);
            var length = Math.Sqrt(x * x + y * y + z * z);
            var unit = (x / length, y / length, z / length);

            var triangle = new Triangle(v0, v1, v2);
            AssertClose(unit, triangle.Normal);
            Assert.Equal(0.5 * length, triangle.Area, 0.5 * length * Tolerance);

            // A ray from the centroid's front side straight at it hits the flat mesh triangle there.
            var mesh = new Mesh([v0, v1, v2], [0, 1, 2]);
            var centroid = new Point3D((v0.x + v1.x + v2.x) / 3, (v0.y + v1.y + v2.y) / 3, (v0.z + v1.z + v2.z) / 3);
            var towards = new Vector3D(-unit.Item1, -unit.Item2, -unit.Item3);
            var sr = new ShadingRecord();
            Assert.True(new MeshTriangle(mesh, 0, smooth: false).Hit(new Ray(centroid - towards, towards), out _, sr));
            AssertClose(unit, sr.Normal);

            mesh.ComputeVertexNormals();
            AssertClose(unit, mesh.Normals![0]);
        }
    }
}
