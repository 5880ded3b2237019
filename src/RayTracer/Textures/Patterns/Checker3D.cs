using RayTracer.Maths;

namespace RayTracer.Textures.Patterns;

/// <summary>Binary solid checkerboard of cubes with side <see cref="Size"/>.</summary>
public sealed class Checker3D(double size = 1.0) : SolidTexture<bool>
{
    public double Size { get; set; } = size;

    public override bool Evaluate(Point3D p)
    {
        // A tiny offset keeps faces lying exactly on a cube boundary from flickering between checks.
        const double eps = -1e-6;
        var i = (long)Math.Floor((p.x + eps) / Size);
        var j = (long)Math.Floor((p.y + eps) / Size);
        var k = (long)Math.Floor((p.z + eps) / Size);
        return ((i + j + k) & 1) == 0;
    }
}
