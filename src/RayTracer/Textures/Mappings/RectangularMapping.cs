using RayTracer.Maths;

namespace RayTracer.Textures.Mappings;

/// <summary>Projects the square [-1, 1]² of the x–z plane onto the image: u from z, v from x.</summary>
public sealed class RectangularMapping : TextureMapping
{
    public override TextureCoordinates Map(Point3D p) =>
        new(Math.Clamp((p.z + 1) / 2, 0, 1), Math.Clamp((p.x + 1) / 2, 0, 1));
}
