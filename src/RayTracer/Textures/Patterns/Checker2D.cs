namespace RayTracer.Textures.Patterns;

/// <summary>Binary checkerboard in (u, v): <see cref="NumU"/> × <see cref="NumV"/> checks, true on "even" checks.</summary>
public sealed class Checker2D(int numU = 8, int numV = 8) : UVTexture<bool>
{
    public int NumU { get; set; } = numU;
    public int NumV { get; set; } = numV;

    public override bool Evaluate(double u, double v)
    {
        var i = (int)Math.Floor(u * NumU);
        var j = (int)Math.Floor(v * NumV);
        return ((i + j) & 1) == 0;
    }
}
