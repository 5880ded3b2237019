using RayTracer.Geometry.Meshes;
using RayTracer.Geometry.Solvers;
using RayTracer.Maths;
using RayTracer.Tracing;

namespace RayTracer.Tests.Geometry.Solvers;

[Collection(TriangleTestCollection.Name)]
public sealed class TriangleTestCounters_Count
{
    [Theory]
    [InlineData(TriangleTest.Algebraic)]
    [InlineData(TriangleTest.Plucker)]
    [InlineData(TriangleTest.PluckerEdges)]
    public void Each_call_of_a_test_is_counted_once_on_its_own_counter(TriangleTest test)
    {
        var mesh = new Mesh([new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)], [0, 1, 2]) { TriangleTest = test };
        var triangle = mesh.CreateTriangles(smooth: false)[0];
        var counter = TriangleTestCounters.For(test);
        var before = counter.Total;
        // From several threads, as a render calls them: the per-thread counts are summed.
        Parallel.For(0, 4, worker =>
        {
            for (var i = 0; i < 250; i++)
                triangle.Intersect(new Ray(new Point3D(0.25, 0.25, 1), new Vector3D(0, 0, -1)), out _);
        });
        Assert.Equal(1000, counter.Total - before);
    }

    [Fact]
    public void A_triangle_keeps_the_test_its_mesh_had_when_it_was_created()
    {
        var mesh = new Mesh([new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)], [0, 1, 2]) { TriangleTest = TriangleTest.Plucker };
        var triangle = mesh.CreateTriangles(smooth: false)[0];
        // A structure built over the triangle packed it for the Plücker test; its shading must agree.
        mesh.TriangleTest = TriangleTest.Algebraic;
        var plucker = TriangleTestCounters.Plucker.Total;
        var algebraic = TriangleTestCounters.Algebraic.Total;
        triangle.Intersect(new Ray(new Point3D(0.25, 0.25, 1), new Vector3D(0, 0, -1)), out _);
        Assert.Equal(TriangleTest.Plucker, triangle.Test);
        Assert.Equal(1, TriangleTestCounters.Plucker.Total - plucker);
        Assert.Equal(0, TriangleTestCounters.Algebraic.Total - algebraic);
    }
}
