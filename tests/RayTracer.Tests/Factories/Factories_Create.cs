using RayTracer.Colors;
using RayTracer.Factories;
using RayTracer.Lights;
using RayTracer.Materials;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Tracing;
using RayTracer.Viewing;

namespace RayTracer.Tests.Factories;

public class Factories_Create
{
    [Fact]
    public void Pinhole_factory_gives_the_requested_field_of_view_at_any_resolution()
    {
        foreach (var width in new[] { 40, 400 })
        {
            var vp = new ViewPlane { HorizontalResolution = width, VerticalResolution = width / 2 };
            var camera = CameraFactory.Pinhole(new Point3D(0, 0, 5), Point3D.Origin, 60, vp);
            camera.GetRay(new Point2D(0.5 * width * vp.PixelSize, 0), vp, out var edge);
            Assert.Equal(30.0, Math.Acos(-edge.d.z) * 180 / Math.PI, 9);
        }
    }

    [Fact]
    public void Orthographic_factory_spans_the_requested_width()
    {
        var vp = new ViewPlane { HorizontalResolution = 50, VerticalResolution = 50 };
        var camera = CameraFactory.Orthographic(new Point3D(0, 0, 5), Point3D.Origin, 10, vp);
        camera.GetRay(new Point2D(0.5 * 50 * vp.PixelSize, 0), vp, out var edge);
        Assert.Equal(5.0, edge.o.x, 12);
    }

    [Fact]
    public void Area_light_factory_adds_a_visible_emitter_and_a_light()
    {
        var world = new World();
        var light = LightFactory.AddSphereLight(world, new Point3D(0, 3, 0), 0.5, 4.0);
        var shape = Assert.Single(world.Objects);
        Assert.Same(light, Assert.Single(world.Lights));
        Assert.IsType<Emissive>(shape.Material);
        Assert.False(shape.CastsShadows);
        var environment = LightFactory.AddEnvironment(world, 0.5);
        Assert.Same(environment, world.Environment);
        Assert.Equal(new RGBColor(0.5, 0.5, 0.5), world.BackgroundRadiance(new Ray(Point3D.Origin, Vector3D.UnitY)));
    }

    [Fact]
    public void Material_factory_glass_is_a_clear_dielectric()
    {
        var glass = MaterialFactory.Glass();
        Assert.Equal(1.5, glass.FresnelBrdf.EtaIn);
        Assert.Equal(RGBColor.White, glass.FilterInside);
        Assert.Equal(0.9, MaterialFactory.Mirror(RGBColor.White).ReflectiveBrdf.Kr);
    }
}
