using Twister;

namespace RayTracer.Viewing;

/// <summary>
/// The classic pinhole's projection surface in the camera's rest frame: a width × height rectangle
/// centred on the −e3 axis at the given distance from the eye, u to the right and v up.
/// </summary>
public sealed class RectangularProjectionSurface : IParametricSurface
{
    public RectangularProjectionSurface(double width, double height, double distance)
    {
        if (!(width > 0) || !(height > 0) || !(distance > 0) || !double.IsFinite(width) || !double.IsFinite(height) || !double.IsFinite(distance))
            throw new ArgumentOutOfRangeException(nameof(width), $"The rectangle ({width} × {height} at distance {distance}) needs positive finite sizes.");
        Width = width;
        Height = height;
        Distance = distance;
    }

    public double Width { get; }

    public double Height { get; }

    public double Distance { get; }

    public TwistablePoint PointAt(double u, double v) => new((u - 0.5) * Width, (v - 0.5) * Height, -Distance);

    /// <summary>∂S/∂u × ∂S/∂v points back at the eye.</summary>
    public TwistableVector NormalAt(double u, double v) => new(0, 0, Width * Height);
}
