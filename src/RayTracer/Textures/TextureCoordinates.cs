namespace RayTracer.Textures;

/// <summary>Surface (u, v) coordinates of a hit, both usually in [0, 1].</summary>
public struct TextureCoordinates
{
    public double u;
    public double v;

    public TextureCoordinates(double u, double v)
    {
        this.u = u;
        this.v = v;
    }
}
