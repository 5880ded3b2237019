namespace RayTracer.Viewing;

/// <summary>Image resolution and pixel geometry.</summary>
public abstract class ViewPlane
{
    public abstract int HorizontalResolution { get; }

    public abstract int VerticalResolution { get; }

    public abstract double PixelSize { get; }
}
