using RayTracer.Integrators;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Tracing;

/// <summary>Small worlds for physics tests: an orthographic camera looking down -z.</summary>
internal static class TestScenes
{
    public static World OrthographicWorld(int size, double pixelSize, Func<World, Integrator> integrator, int samples = 1)
    {
        var world = new World();
        world.ViewPlane = new ViewPlane { HorizontalResolution = size, VerticalResolution = size, PixelSize = pixelSize, MaxDepth = 20 };
        world.ViewPlane.SetSamples(samples);
        var camera = new OrthographicCamera { Eye = new Point3D(0, 0, 10), LookAt = Point3D.Origin };
        camera.ComputeUVW();
        world.Camera = camera;
        world.Integrator = integrator(world);
        return world;
    }

    /// <summary>View-plane centre of a pixel (row 0 at the top), matching the camera's convention.</summary>
    public static (double X, double Y) PixelCentre(ViewPlane vp, int column, int row) =>
        (vp.PixelSize * (column - 0.5 * vp.HorizontalResolution + 0.5),
         vp.PixelSize * (vp.VerticalResolution - 1 - row - 0.5 * vp.VerticalResolution + 0.5));
}
