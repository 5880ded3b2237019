using RayTracer.Maths;

namespace RayTracer.Textures.Patterns;

/// <summary>Binary squares of side <see cref="Size"/> on the x–z plane (for floors), ignoring height.</summary>
public sealed class PlaneChecker(double size = 1.0) : SolidTexture<bool>
{
    public double Size { get; set; } = size;

    public override bool Evaluate(Point3D p)
    {
        var i = (long)Math.Floor(p.x / Size);
        var k = (long)Math.Floor(p.z / Size);
        return ((i + k) & 1) == 0;
    }
}
