using RayTracer.Maths;

namespace RayTracer.Textures.Mappings;

/// <summary>Maps a local hit point to (u, v) in [0, 1]² for image and other 2D textures.</summary>
public abstract class TextureMapping
{
    public abstract TextureCoordinates Map(Point3D localHitPoint);

    /// <summary>Azimuth about +y measured from +z towards +x, in [0, 2π).</summary>
    protected static double Azimuth(Point3D p)
    {
        var phi = Math.Atan2(p.x, p.z);
        return phi < 0 ? phi + MathConstants.TwoPi : phi;
    }
}
