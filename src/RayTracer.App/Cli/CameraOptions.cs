using System.CommandLine;
using System.Globalization;
using RayTracer.Factories;
using RayTracer.Maths;
using RayTracer.Scenes;

namespace RayTracer.Cli;

/// <summary>
/// The render command's camera options: <c>--camera NAME[:DEGREES]</c> puts the scene behind any camera
/// of <see cref="CameraCatalog"/>, and <c>--eye</c>, <c>--look-at</c>, <c>--up</c> (each <c>X,Y,Z</c>)
/// move whichever camera is used. What is not given is taken from the scene's own camera.
/// </summary>
internal sealed class CameraOptions
{
    public Option<string?> Camera { get; } = new("--camera")
    {
        Description = $"See the scene through another camera: {string.Join(", ", CameraCatalog.Names)}; an optional field of view in degrees follows a colon",
        HelpName = "NAME[:DEGREES]",
    };

    public Option<Point3D?> Eye { get; } = PointOption("--eye", "Camera position");
    public Option<Point3D?> LookAt { get; } = PointOption("--look-at", "Point the camera looks at");

    public Option<Vector3D?> Up { get; } = new("--up")
    {
        Description = "Direction that appears upwards in the image (any length but zero)",
        HelpName = "X,Y,Z",
        CustomParser = result =>
        {
            if (ParseTriple(result.Tokens.Single().Value, "--up", out var error) is not { } t)
            {
                result.AddError(error!);
                return null;
            }
            var up = new Vector3D(t.x, t.y, t.z);
            if (up.LengthSquared == 0)
            {
                result.AddError("--up must not be the zero vector: it gives the direction of image-up");
                return null;
            }
            return up;
        },
    };

    public CameraOptions()
    {
        Camera.Validators.Add(result =>
        {
            if (result.GetValueOrDefault<string?>() is { } text && !CameraCatalog.TryParse(text, out _, out _, out var error))
                result.AddError($"--camera: {error}");
        });
    }

    public IEnumerable<Option> All => [Camera, Eye, LookAt, Up];

    /// <summary>The options as given; nulls for those left out.</summary>
    public CameraRequest Read(ParseResult parsed) => new(parsed.GetValue(Camera), parsed.GetValue(Eye), parsed.GetValue(LookAt), parsed.GetValue(Up));

    private static Option<Point3D?> PointOption(string name, string description) => new(name)
    {
        Description = description,
        HelpName = "X,Y,Z",
        CustomParser = result =>
        {
            if (ParseTriple(result.Tokens.Single().Value, name, out var error) is { } t)
                return new Point3D(t.x, t.y, t.z);
            result.AddError(error!);
            return null;
        },
    };

    private static (double x, double y, double z)? ParseTriple(string text, string name, out string? error)
    {
        var parts = text.Split(',');
        var values = new double[3];
        error = null;
        if (parts.Length == 3 && parts.Select((p, i) =>
                double.TryParse(p.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) && double.IsFinite(values[i])).All(ok => ok))
            return (values[0], values[1], values[2]);
        error = $"{name} expects three finite numbers separated by commas (X,Y,Z), got '{text}'";
        return null;
    }
}

/// <summary>The camera options of one render; apply them to the built world.</summary>
internal sealed record CameraRequest(string? Camera, Point3D? Eye, Point3D? LookAt, Vector3D? Up)
{
    public bool IsEmpty => Camera is null && Eye is null && LookAt is null && Up is null;

    /// <summary>
    /// Replaces or re-orients the world's camera. Returns the problem (eye on the look-at point, a
    /// field of view the camera refuses) as a message, or null when the world is ready.
    /// </summary>
    public string? ApplyTo(World world)
    {
        if (IsEmpty)
            return null;
        var current = world.Camera ?? throw new InvalidOperationException("The world has no camera.");
        var eye = Eye ?? current.Eye;
        var lookAt = LookAt ?? current.LookAt;
        var up = Up ?? current.Up;
        try
        {
            if (Camera is { } text)
            {
                if (!CameraCatalog.TryParse(text, out var choice, out var degrees, out var error))
                    return error;
                world.Camera = choice.Create(degrees, world.ViewPlane, eye, lookAt, up);
            }
            else
            {
                Viewing.GpcmOrientation.Validate(eye, lookAt, up);
                current.Eye = eye;
                current.LookAt = lookAt;
                current.Up = up;
                current.Aim();
            }
        }
        catch (ArgumentException e)
        {
            return e.Message.Split(" (Parameter", 2)[0];
        }
        return null;
    }
}
