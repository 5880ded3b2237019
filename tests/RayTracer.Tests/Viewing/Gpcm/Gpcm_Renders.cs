using RayTracer.Factories;
using RayTracer.Maths;
using RayTracer.Scenes;
using RayTracer.Scenes.Gpcm;
using RayTracer.Viewing;

namespace RayTracer.Tests.Viewing.Gpcm;

/// <summary>Whole images through a generalized pinhole camera against the hand camera it reproduces.</summary>
public class Gpcm_Renders
{
    private static FrameBuffer Render(string camera, double degrees, int width, int height, Point3D eye, Point3D lookAt, Vector3D up)
    {
        var world = new GpcmSphericalScene().Build(new SceneSettings { Width = width, Height = height, SamplesPerPixel = 4 });
        Assert.True(CameraCatalog.TryFind(camera, out var choice));
        world.Camera = choice.Create(degrees, world.ViewPlane, eye, lookAt, up);
        return new Renderer(new RenderOptions { Seed = 11, Threads = 2 }).Render(world);
    }

    public static TheoryData<string, string, double, int, int> Pairs => new()
    {
        { "rectangular", "pinhole", 70, 48, 36 },
        { "spherical", "spherical-hand", 360, 64, 32 },
        { "spherical", "spherical-hand", 120, 48, 36 },
        { "fisheye", "fisheye-hand", 180, 40, 40 },
        { "fisheye", "fisheye-hand", 360, 40, 40 },
    };

    [Theory]
    [MemberData(nameof(Pairs))]
    public void Gpcm_and_hand_camera_render_the_same_image_for_a_fixed_seed(string gpcm, string hand, double degrees, int width, int height)
    {
        // A tilted up direction and an eye off the gallery's centre, so the orientation does real work.
        var eye = new Point3D(0.3, 1.7, 0.4);
        var lookAt = new Point3D(-2, 0.9, -5);
        var up = new Vector3D(0.2, 1, 0.1);
        var a = Render(gpcm, degrees, width, height, eye, lookAt, up);
        var b = Render(hand, degrees, width, height, eye, lookAt, up);
        Assert.Equal(b.Width, a.Width);
        Assert.Equal(b.Height, a.Height);

        // Rays agree to about 1e-15, so a pixel could differ only where a ray grazes an edge; count them.
        var different = 0;
        var largest = 0.0;
        for (var i = 0; i < a.Pixels.Length; i++)
        {
            var d = Math.Max(Math.Abs(a.Pixels[i].r - b.Pixels[i].r), Math.Max(Math.Abs(a.Pixels[i].g - b.Pixels[i].g), Math.Abs(a.Pixels[i].b - b.Pixels[i].b)));
            largest = Math.Max(largest, d);
            if (d > 1e-9)
                different++;
        }
        Assert.True(different == 0, $"{different} of {a.Pixels.Length} pixels differ by more than 1e-9 (largest {largest})");
    }
}
