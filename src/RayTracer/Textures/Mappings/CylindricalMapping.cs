using RayTracer.Maths;

namespace RayTracer.Textures.Mappings;

/// <summary>Wraps the image around the unit cylinder about +y for y in [-1, 1].</summary>
public sealed class CylindricalMapping : TextureMapping
{
    public override TextureCoordinates Map(Point3D p) =>
        new(Azimuth(p) * MathConstants.InvTwoPi, Math.Clamp((p.y + 1) / 2, 0, 1));
}
