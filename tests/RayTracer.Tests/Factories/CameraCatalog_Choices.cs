using RayTracer.Factories;
using RayTracer.Maths;
using RayTracer.Viewing;

namespace RayTracer.Tests.Factories;

public class CameraCatalog_Choices
{
    private static readonly ViewPlane Plane = new() { HorizontalResolution = 80, VerticalResolution = 40 };

    [Theory]
    [InlineData("cylindrical", 360)]
    [InlineData("cylindrical:180", 180)]
    [InlineData("CONIC:90", 90)]
    [InlineData("rectangular:179.5", 179.5)]
    [InlineData("fisheye", 180)]
    [InlineData("spherical:1e2", 100)]
    public void Reads_a_name_with_an_optional_field_of_view(string text, double degrees)
    {
        Assert.True(CameraCatalog.TryParse(text, out var choice, out var read, out var error), error);
        Assert.Equal(text.Split(':')[0].ToLowerInvariant(), choice.Name);
        Assert.Equal(degrees, read);
    }

    [Theory]
    [InlineData("lens", "unknown camera 'lens'")]
    [InlineData("", "unknown camera ''")]
    [InlineData("rectangular:180", "less than 180°")]
    [InlineData("cylindrical:400", "at most 360°")]
    [InlineData("fisheye:0", "more than 0°")]
    [InlineData("spherical:-90", "more than 0°")]
    [InlineData("spherical:wide", "'wide' is not a number")]
    [InlineData("spherical:NaN", "is not a number")]
    [InlineData("conic:", "'' is not a number")]
    public void Refuses_unknown_names_and_bad_fields_of_view_with_a_message(string text, string message)
    {
        Assert.False(CameraCatalog.TryParse(text, out var choice, out _, out var error));
        Assert.Null(choice);
        Assert.Contains(message, error);
    }

    [Fact]
    public void Every_camera_is_built_oriented_and_sees_the_look_at_point_at_the_centre()
    {
        var eye = new Point3D(2, 3, -1);
        var lookAt = new Point3D(-4, 1, 6);
        var up = new Vector3D(0.1, 0.2, 1);
        foreach (var choice in CameraCatalog.All)
        {
            var degrees = choice.Name.StartsWith("conic", StringComparison.Ordinal) ? 270 : choice.DefaultDegrees;
            var camera = choice.Create(degrees, Plane, eye, lookAt, up);
            Assert.True(camera.GetRay(new Point2D(0, 0), Plane, out var ray), choice.Name);
            Assert.True((ray.d.Normalized() - (lookAt - eye).Normalized()).Length < 1e-12, $"{choice.Name}: {ray.d}");
            Assert.Equal(eye, ray.o);
        }
    }

    [Fact]
    public void Create_refuses_coinciding_points_a_zero_up_and_a_bad_field_of_view()
    {
        Assert.True(CameraCatalog.TryFind("pinhole", out var pinhole));
        var p = new Point3D(1, 2, 3);
        Assert.Contains("distinct", Assert.Throws<ArgumentException>(() => pinhole.Create(60, Plane, p, p, Vector3D.UnitY)).Message);
        Assert.Contains("nonzero", Assert.Throws<ArgumentException>(() => pinhole.Create(60, Plane, p, Point3D.Origin, new Vector3D(0, 0, 0))).Message);
        Assert.Contains("less than 180°", Assert.Throws<ArgumentOutOfRangeException>(() => pinhole.Create(180, Plane, p, Point3D.Origin, Vector3D.UnitY)).Message);
    }
}
