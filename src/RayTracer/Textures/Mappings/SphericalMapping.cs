using RayTracer.Maths;

namespace RayTracer.Textures.Mappings;

/// <summary>Latitude–longitude map of the unit sphere: u from the azimuth about +y, v = 1 at the north pole (+y).</summary>
public sealed class SphericalMapping : TextureMapping
{
    public override TextureCoordinates Map(Point3D p)
    {
        var length = Math.Sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        var theta = Math.Acos(Math.Clamp(p.y / length, -1, 1));
        return new TextureCoordinates(Azimuth(p) * MathConstants.InvTwoPi, 1 - theta * MathConstants.InvPi);
    }
}
