using RayTracer.Colors;
using RayTracer.Geometry.Universal;
using RayTracer.Integrators;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Tests.Tracing;
using RayTracer.Tracing;

namespace RayTracer.Tests.Integrators;

public class Integrator_Allocations
{
    [Fact]
    public void Tracing_recursive_rays_allocates_nothing_once_the_thread_is_warm()
    {
        // Two facing mirrors make every primary ray recurse to the maximum depth, so each level of
        // nesting needs its own shading record while its parent is still being shaded.
        var world = TestScenes.OrthographicWorld(1, 0.01, w => new WhittedIntegrator(w));
        world.ViewPlane.MaxDepth = 6;
        world.AmbientLight = new AmbientLight(1.0);
        world.Add(new PointLight(new Point3D(0.5, 0.5, 1.5), 1.0));
        var mirror = new Reflective(0.3, 0.4, RGBColor.White, 0, 10, 0.5, RGBColor.White);
        world.Add(new Plane(Point3D.Origin, new Normal3D(0, 0, 1)) { Material = mirror });
        world.Add(new Plane(new Point3D(0, 0, 2), new Normal3D(0, 0, -1)) { Material = mirror });
        var tracer = world.Integrator!;
        var ray = new Ray(new Point3D(0.1, 0.2, 1), new Vector3D(0.01, 0, -1));
        var first = tracer.TraceRay(ray, 0);

        // The runtime itself may allocate on this thread while the JIT replaces the first code of the
        // loop (a few kilobytes, once, seen under load): rounds of 1000 rays until one allocates
        // nothing. An allocation per ray would show in every round.
        var last = RGBColor.Black;
        long allocated = -1;
        for (var round = 0; round < 5 && allocated != 0; round++)
        {
            var before = GC.GetAllocatedBytesForCurrentThread();
            for (var i = 0; i < 1000; i++)
                last = tracer.TraceRay(ray, 0);
            allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        }

        Assert.Equal(0, allocated);
        Assert.Equal(first, last);
    }
}
